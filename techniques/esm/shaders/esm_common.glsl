// Extended shadow map encoding (Bujnak, sections 3.1, 4.1, 4.2), shared by the silhouette-quad
// pass that writes it and the shadow test that reads it. Units: texels of the map's tile.
//
// A silhouette quad covers a band across its edge from BAND_IN texels inside the occluder to
// BAND_OUT texels outside it (the paper's extrusion +q outwards, -q/2 inwards). Its linear quad
// coordinate t runs 0 -> 1 across the band, so the edge passes through t = 1/3 and t = 1/2 lies
// 0.707 texels outside the edge (section 4.2): BAND_OUT = 2 sqrt 2, BAND_IN = sqrt 2.
//
// Channels of the RGBA32F map:
//   r  1 - edge_transfer(t): the INVERTED lit-ness, so MAX blending of overlapping quads keeps
//      the most shadowed one ("minimal distance, maximal value", section 4.1); 0 = no quad
//   g  unused (0): the map depth, the paper's green channel, is the depth attachment, which the
//      quads and the shadow test read (with its polygon offset, as plain shadow mapping)
//   b  edge depth: window depth of the silhouette edge at this texel (MAX: the farthest edge)
//   a  silhouette mask: 1 where a quad wrote
const float BAND_OUT = 2.8284271;  // texels outside the edge
const float BAND_IN = 1.4142136;   // texels inside the occluder
const float EDGE_T = 1.0 / 3.0;    // quad coordinate of the edge

// Quad coordinate of a signed distance d from the edge (texels, > 0 outside the occluder).
float quad_coordinate(float d) { return (d + BAND_IN) / (BAND_IN + BAND_OUT); }

// Section 4.2's transfer of the linear quad coordinate: a guard zone t in [0, 0.25] on the
// occluder side reads as full shadow (0), then lit-ness rises linearly to 1 at the band's outer
// end. The guard zone keeps the far (inner) end of one quad from lifting the interpolated value
// of another quad crossing below it, which opened lit holes between the shadow of the opaque
// triangles and that of the quads (the paper's Figure 9). Over the bilinear footprint of the
// shadow boundary (+-1 texel) the transfer is linear, so the boundary stays straight.
const float GUARD_T = 0.25;
float edge_transfer(float t) { return clamp((t - GUARD_T) / (1.0 - GUARD_T), 0.0, 1.0); }

// Lit-ness of the edge itself.
float edge_litness() { return edge_transfer(EDGE_T); }
