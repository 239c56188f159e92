// Extended shadow map encoding (Bujnak, sections 3.1, 4.1, 4.2), shared by the silhouette-quad
// pass that writes it and the shadow test that reads it. Units: texels of the map's tile.
//
// A silhouette quad covers a band across its edge from BAND_IN texels inside the occluder to
// BAND_OUT texels outside it (the paper's extrusion +q outwards, -q/2 inwards). Its linear quad
// coordinate t runs 0 -> 1 across the band, so the edge passes through t = 1/3 and t = 1/2 lies
// 0.707 texels outside the edge (section 4.2): BAND_OUT = 2 sqrt 2, BAND_IN = sqrt 2.
//
// The map is three R32F textures, 4 bytes a texel each (an RG32F pair until the silhouettes could be
// written by compute: image atomics take single 32-bit channels):
//   edge        QUAD_MARK + 1 - edge_transfer(t) where a quad wrote, the INVERTED lit-ness, so
//               MAX blending of overlapping quads keeps the most shadowed one ("minimal distance,
//               maximal value", section 4.1); below QUAD_MARK where none did (the depth pass's
//               "no edge" value). The mark is the silhouette mask: every quad value lies above
//               every "no edge" value, so MAX keeps it, and one gather says whether a footprint
//               has quads.
//   edge_depth  window depth of the silhouette edge at this texel (MAX: the farthest edge)
//   edge_near   the NEAREST edge at this texel, depth and lit-ness together (esm_encode_near): 0
//               where no quad wrote. Where silhouettes of two surfaces meet within the band (a
//               contact, a beam on a column, a facet next to another part of the same mesh), the
//               farthest edge is often the receiver's own, which never shadows it; the nearest
//               one, in front of the receiver, does (the issue's "two edges per texel").
// All are non-negative where a quad wrote or MAX blending cleared them, so a compute writer can
// MAX their bit patterns as unsigned integers.
// The map depth, the paper's green channel, is the depth attachment, which the quads and the
// shadow test read (with its polygon offset, as plain shadow mapping).
const float QUAD_MARK = 2.0;        // added to r where a quad wrote; "no edge" r is < 1
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

// A map texel as (inverted lit-ness, 0, edge depth, mask), from its stored (edge, edge_depth).
vec4 esm_decode(vec2 stored) {
  bool quad = stored.x >= QUAD_MARK;
  return vec4(quad ? stored.x - QUAD_MARK : stored.x, 0.0, stored.y, quad ? 1.0 : 0.0);
}

// edge_near packs the edge's depth, rounded up to 1/65534 steps and inverted, as the integer part
// (1 .. 65535: MAX keeps the nearest edge) and its inverted lit-ness in 1/256 steps as the fraction
// (a float's 24 bits hold both below 65536). Rounding the depth up makes "behind it" stricter.
const float NEAR_STEPS = 65535.0;
float esm_encode_near(float inverted_litness, float edge_depth) {
  float steps = ceil(clamp(edge_depth, 0.0, 1.0) * (NEAR_STEPS - 1.0));
  return NEAR_STEPS - steps + floor(clamp(inverted_litness, 0.0, 1.0) * 255.0 + 0.5) / 256.0;
}

// The nearest edge as a texel (inverted lit-ness, 0, edge depth, mask), from edge_near.
vec4 esm_decode_near(float stored) {
  if (stored < 1.0) return vec4(0.0);
  float steps = floor(stored);
  return vec4((stored - steps) * (256.0 / 255.0), 0.0, (NEAR_STEPS - steps) / (NEAR_STEPS - 1.0), 1.0);
}

// What a quad writes: (edge, edge_depth, edge_near).
vec3 esm_encode_quad(float inverted_litness, float edge_depth) {
  return vec3(QUAD_MARK + inverted_litness, edge_depth, esm_encode_near(inverted_litness, edge_depth));
}
