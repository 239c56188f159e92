// Extended shadow map encoding (Bujnak, sections 3.1, 4.1, 4.2), shared by the silhouette-quad
// pass that writes it and the shadow test that reads it. Units: texels of the map's tile.
//
// A silhouette quad covers a band across its edge from BAND_IN texels inside the occluder to
// BAND_OUT texels outside it. Its linear quad coordinate t runs 0 -> 1 across the band; lit-ness
// is t (section 4.2's transfer, without its guard zone: distance_litness). BAND_OUT is the
// paper's extrusion q = 2 sqrt 2 outwards. Inwards the paper extrudes q/2 = sqrt 2 and flattens
// t <= 0.25 (0.35 texels inside the edge) to full shadow, the guard zone; here the band ends one
// texel inside, where a boundary's bilinear footprint ends, and is linear throughout. The guard
// zone moved every interpolated boundary into the occluder by up to 0.2 texels wherever the
// footprint's inner texel lay deeper than 0.35 (every shadow came out narrower), and a longer
// inner band reaches through objects thinner than it (bars, pickets) onto the ground beyond
// (docs/results/esm.md, 2026-11-29, "a linear band one texel inside").
//
// The map is three R32F textures, 4 bytes a texel each (an RG32F pair until the silhouettes could be
// written by compute: image atomics take single 32-bit channels):
//   edge        QUAD_MARK + the key of the texel's signed distance from its edge (quad_key) and,
//               below the key's last step, the edge's outward direction (esm_encode_edge) where a
//               quad wrote; below QUAD_MARK where none did (the depth pass's "no edge" value). The
//               key orders overlapping quads for MAX (section 4.1): inside an occluder beats
//               outside (the shadows of several casters are their union), and on either side the
//               edge nearest the texel wins. The mark is the silhouette mask: every key lies above
//               every "no edge" value, so MAX keeps it, and one gather says whether a footprint
//               has quads. Distance and direction are the texel's edge as a line, which the shadow
//               test evaluates at the receiver (esm_mask.comp.glsl, "edge lines").
//   edge_depth  window depth of the silhouette edge at this texel (MAX: the farthest edge)
//   edge_near   the nearest edge at this texel in depth, its depth and lit-ness together
//               (esm_encode_near): 0 where no quad wrote. Where silhouettes of two surfaces meet
//               within the band (a contact, a beam on a column, a facet next to another part of the
//               same mesh), the farthest edge is often the receiver's own, which never shadows it;
//               the nearest one, in front of the receiver, does (the issue's "two edges per texel").
// All are non-negative where a quad wrote or MAX blending cleared them, so a compute writer can
// MAX their bit patterns as unsigned integers.
// The map depth, the paper's green channel, is the depth attachment, which the quads and the
// shadow test read (with its polygon offset, as plain shadow mapping).
const float QUAD_MARK = 2.0;        // added to the key where a quad wrote; "no edge" values are < 1
const float BAND_OUT = 2.8284271;  // texels outside the edge
const float BAND_IN = 1.0;         // texels inside the occluder

// Quad coordinate of a signed distance d from the edge (texels, > 0 outside the occluder).
float quad_coordinate(float d) { return (d + BAND_IN) / (BAND_IN + BAND_OUT); }

// Lit-ness at `d` texels from the edge (> 0 outside the occluder).
float distance_litness(float d) { return clamp(quad_coordinate(d), 0.0, 1.0); }

// Lit-ness of the edge itself.
float edge_litness() { return distance_litness(0.0); }

// "Deep inside" an occluder: where the paper's guard zone was, sqrt 2 / 4 texels inside the edge
// or deeper. The shadow test trusts the depth map over an edge that puts a texel there
// (esm_mask.comp.glsl).
const float DEEP_INSIDE = -0.35355339;
float deep_inside_litness() { return distance_litness(DEEP_INSIDE); }

// The edge channel's key of a texel `d` texels from its quad's edge: outside (d > 0) in [0, 1),
// falling with the distance; inside in [1, 2], rising towards the edge. MAX over the quads of a
// texel then keeps an inside over any outside, and the nearest edge on either side. Inside an
// object thinner than the band both of its edges reach a texel, and the nearer one is the one
// whose boundary passes there; MAX of the inverted lit-ness (the paper's "minimal distance") kept
// the farther edge and widened the shadows of thin bars and pickets (same section).
float quad_key(float d) { return d > 0.0 ? 1.0 - d / BAND_OUT : 2.0 + max(d, -BAND_IN) / BAND_IN; }
float key_distance(float key) { return key < 1.0 ? (1.0 - key) * BAND_OUT : (key - 2.0) * BAND_IN; }

// The edge channel's value where a quad wrote: QUAD_MARK + the key in 2^-14 steps, and the edge's
// outward direction (from the edge towards the texel beyond its ends) in 256 steps as the 8 bits
// below them. Between 2 and 4 a float's last bit is 2^-22, so the sum is exact, MAX still orders
// by the key first, and the direction always belongs to the edge whose key won. Steps of 2^-14
// are 1.7e-4 texels of distance outside, 6e-5 inside. The direction is its "diamond angle" (the
// position on the unit diamond |x| + |y| = 1, 0 to 4 counterclockwise from +x): no trigonometry
// in the writers or the shadow test, steps of 0.9 to 1.8 degrees, which move a line at most 0.03
// texels a texel away.
const float KEY_STEPS = 16384.0;
const float DIRECTION_STEPS = 256.0;
const float EDGE_STEP = 1.0 / (KEY_STEPS * DIRECTION_STEPS);  // the last bit of a float in [2, 4)
float diamond_angle(vec2 v) {
  float s = v.y / (abs(v.x) + abs(v.y));
  return v.x < 0.0 ? 2.0 - s : (v.y < 0.0 ? 4.0 + s : s);
}
vec2 diamond_direction(float p) {
  return normalize(vec2(p < 2.0 ? 1.0 - p : p - 3.0, p < 1.0 ? p : (p < 3.0 ? 2.0 - p : p - 4.0)));
}
float esm_encode_edge(float key, vec2 outward) {
  float key_steps = min(floor(key * KEY_STEPS), 2.0 * KEY_STEPS - 1.0);  // below 4: one exponent
  float direction = mod(floor(diamond_angle(outward) * (DIRECTION_STEPS / 4.0) + 0.5), DIRECTION_STEPS);
  return QUAD_MARK + (key_steps * DIRECTION_STEPS + direction) * EDGE_STEP;
}
float esm_edge_key(float stored) { return floor((stored - QUAD_MARK) / EDGE_STEP / DIRECTION_STEPS) / KEY_STEPS; }
vec2 esm_edge_outward(float stored) {
  float steps = (stored - QUAD_MARK) / EDGE_STEP;
  return diamond_direction((steps - floor(steps / DIRECTION_STEPS) * DIRECTION_STEPS) * (4.0 / DIRECTION_STEPS));
}

// A map texel as (1 - lit-ness, signed distance, edge depth, mask), from its stored (edge, edge_depth).
vec4 esm_decode(vec2 stored) {
  if (stored.x < QUAD_MARK) return vec4(stored.x, 0.0, stored.y, 0.0);
  float d = key_distance(esm_edge_key(stored.x));
  return vec4(1.0 - distance_litness(d), d, stored.y, 1.0);
}

// edge_near packs the edge's depth, rounded up to 1/65534 steps and inverted, as the integer part
// (1 .. 65535: MAX keeps the nearest edge) and its inverted lit-ness in 1/256 steps as the fraction
// (a float's 24 bits hold both below 65536). Rounding the depth up makes "behind it" stricter.
const float NEAR_STEPS = 65535.0;
float esm_encode_near(float inverted_litness, float edge_depth) {
  float steps = ceil(clamp(edge_depth, 0.0, 1.0) * (NEAR_STEPS - 1.0));
  return NEAR_STEPS - steps + floor(clamp(inverted_litness, 0.0, 1.0) * 255.0 + 0.5) / 256.0;
}

// The nearest edge as a texel (1 - lit-ness, 0, edge depth, mask), from edge_near (no distance).
vec4 esm_decode_near(float stored) {
  if (stored < 1.0) return vec4(0.0);
  float steps = floor(stored);
  return vec4((stored - steps) * (256.0 / 255.0), 0.0, (NEAR_STEPS - steps) / (NEAR_STEPS - 1.0), 1.0);
}

// What a quad writes at `d` texels from its edge, `outward` its unit direction there: (edge,
// edge_depth, edge_near).
vec3 esm_encode_quad(float d, vec2 outward, float edge_depth) {
  return vec3(esm_encode_edge(quad_key(d), outward), edge_depth, esm_encode_near(1.0 - distance_litness(d), edge_depth));
}
