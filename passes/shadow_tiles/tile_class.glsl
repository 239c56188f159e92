// The classes of the tile-class texture (R8, one texel per screen tile) written by the tile
// classifier (shadow_tiles.comp.glsl): lit white, umbra black, penumbra grey, so the texture
// itself is the overlay the resource viewer shows.
const float TILE_UMBRA = 0.0;
const float TILE_PENUMBRA = 0.5;
const float TILE_LIT = 1.0;
// The class of a texel read back from R8 (0, 128/255 or 1).
float tile_class_of(float texel) { return texel < 0.25 ? TILE_UMBRA : texel > 0.75 ? TILE_LIT : TILE_PENUMBRA; }
