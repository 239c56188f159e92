#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// The extended shadow map's shadow test (Bujnak, section 3.2), one receiver pixel per thread:
// the map depth and the edge depth are compared point-filtered at the nearest texel, the edge
// distance comes from the 2x2 texels around the receiver (their edges as lines, or the paper's
// bilinear interpolation), and the result is an anti-aliased hard shadow (1 = lit, 0 = umbra).
//
// The paper's lookup on (depth flag, edge flag, distance) is a table; with float targets and a
// compute shader it becomes:
//   a = the receiver is behind the occluder at the nearest texel (plain shadow mapping);
//   b = the footprint's texels have silhouette quads and the receiver is behind an edge of each:
//       the farthest, or else the nearest, which then stands alone (map_texel; the paper reads only
//       the nearest texel's single edge depth);
//   !b  -> a ? 0 : 1, exactly the plain shadow map;
//   a, and the nearest texel is not inside its edge -> 0: it is covered by an occluder other
//       than that edge's own surface (another object whose edge crosses, Figures 9-11), which no
//       edge may lighten (no lit holes where silhouettes cross);
//   a texel of the footprint deep inside its edge (DEEP_INSIDE) with nothing in front of the
//       receiver: the edge data contradicts the depth map, as it does where dense silhouettes
//       overlap (thin objects, neighbours a few texels apart): that texel gives no edge line, and
//       without one from another texel (or with edge_lines off) -> a ? 0 : 1;
//   otherwise -> the receiver's distance from the texels' edge lines decides (edge_line_distance),
//       with a ramp one pixel wide on screen; with edge_lines off, or where no texel gives a line,
//       the bilinear lit-ness: a texel contributes its quad's lit-ness (0 when it lies outside its
//       edge and is occluded in front of the receiver: the same rule per texel), or its plain
//       depth test's 0 or 1 without one.
// The paper shifts the boundary 0.707 texels outwards so that its 8-bit lookup could always
// trust a; with the rule above the true edge is kept (boundary_shift = 0), the paper's shift is
// a parameter.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "esm_common.glsl"
#include "esm_views.glsl"
layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_shadow_map;   // the depth pass's biased depth (nearest texel fetches)
uniform sampler2D u_edge;         // the extended map's three channels (esm_common.glsl): texel
uniform sampler2D u_edge_depth;   // fetches, and a gather of the edge's marks
uniform sampler2D u_edge_near;
uniform float u_depth_bias;       // window depth units, subtracted from the receiver depth
uniform float u_boundary_shift;   // boundary_shift: texels outwards from the edge
uniform float u_aa_width;         // pixels; 0 = a binary edge
uniform float u_edge_bias_texels; // edge_bias: texels of the receiver's own depth slope
uniform bool u_nearest_edge;      // nearest_edge: read edge_near where the farthest edge is not in front
uniform bool u_edge_lines;        // edge_lines: the texels' edges as lines at the receiver (else bilinear)
uniform bool u_edge_plane;        // edge_plane: behind an edge's line only where the receiver's plane is too
uniform mat4 u_inv_view_proj;     // camera clip -> world
uniform vec2 u_screen;            // pixels

// Where the camera ray through pixel-space point `px` meets the plane (p, n).
vec3 on_plane(vec2 px, vec3 p, vec3 n) {
  vec2 ndc = px / u_screen * 2.0 - 1.0;
  vec4 a = u_inv_view_proj * vec4(ndc, -1.0, 1.0), b = u_inv_view_proj * vec4(ndc, 1.0, 1.0);
  vec3 o = a.xyz / a.w, d = b.xyz / b.w - o;
  float denom = dot(d, n);
  if (abs(denom) < 1e-12) return p;
  return o + d * (dot(p - o, n) / denom);
}

// Window depth change per texel (map x and y) of the receiver's surface, from how map coordinates
// and depth change per pixel along x (cx) and y (cy); a surface seen edge-on gets a huge slope.
vec2 receiver_gradient(vec3 cx, vec3 cy) {
  float det = cx.x * cy.y - cx.y * cy.x;
  if (abs(det) < 1e-12) return vec2(1e9);
  return vec2(cx.z * cy.y - cy.z * cx.y, cy.z * cx.x - cx.z * cy.x) / det;
}

// The receiver as the edges see it: its biased depth, its surface's depth gradient per texel, the
// edge bias that gradient gives (edge_bias texels of it) and its place in the 2x2 footprint
// (texels from the first texel's centre).
struct Receiver {
  float z;
  vec2 dz;
  float edge_bias;
  vec2 f;
};

// map_texel's mask (.a): a quad's texel, or its nearest edge alone (depth and lit-ness, no distance).
const float QUAD_TEXEL = 1.0, NEAREST_EDGE_ONLY = 2.0;
bool has_quad(vec4 texel) { return texel.a > 0.5; }

// edge_plane: where the texel has its edge as a line (its own quads), the receiver is behind the
// edge only if its tangent plane, extended to the line, is also behind the edge by more than this
// many texels of its depth gradient. A surface never shadows itself along its own silhouette
// edge, and that edge lies in its plane (a sheet's rim, the lit facet of a sharp edge) or, for a
// convex surface, in front of it, however far the receiver is from it and whichever way the
// surface slopes; edge_bias alone, a depth margin at the receiver, had to cover the surface's
// rise over the whole band, which handed the plain map's staircase to shadows cast by an edge
// less than that in front of the receiver (a window frame on its pane: contact slivers). With the
// plane, edge_bias went from 0.5 to 0.1 texels: edge error at 512^2, 1080p, llvmpipe,
// CesiumMilkTruck 0.0459 -> 0.0394, FlightHelmet 0.0548 -> 0.0520, showcase 0.0221 -> 0.0209
// (docs/results/esm.md, "the receiver's plane at the edge").
const float EDGE_PLANE_TOLERANCE = 0.25;

// The receiver is behind the texel's edge: deeper than it by more than edge_bias and, with
// edge_plane, its plane at the texel's edge line too. `outward` is the line's direction, `centre`
// the texel's offset in the footprint.
bool behind_edge(vec4 texel, vec2 outward, vec2 centre, Receiver r) {
  if (r.z <= texel.b + r.edge_bias) return false;
  if (!u_edge_plane || texel.a != QUAD_TEXEL) return true;
  float at = texel.g + dot(r.f - centre, outward);  // the receiver's signed distance from the line
  return r.z - at * dot(r.dz, outward) > texel.b + EDGE_PLANE_TOLERANCE * length(r.dz);
}

// A map texel as the receiver at depth z sees it. Behind its farthest edge: every quad of the texel
// (the distance the edge key kept, MAX). Else behind its nearest edge only: that edge alone, as if the
// farther ones (the receiver's own, at a contact) were not there. Else the texel keeps its farthest
// edge, and the receiver, behind none, gets the plain test (rule b below). The nearest edge took
// esm's edge error at 512^2, 1080p, H200 from 0.0199 to 0.0146 on colonnade and 0.0416 to 0.0327
// on Fox, 0.74-1.01x on 11 scenes (docs/results/esm.md, 2026-11-29).
// The texel is the one at `centre` in the footprint; `outward` its edge line's direction (where it
// has a quad), decoded once for the plane and the edge lines; `behind`: the receiver is behind the
// edge the texel keeps.
vec4 map_texel(ivec2 i0, vec2 centre, Receiver r, out vec2 outward, out bool behind) {
  ivec2 p = i0 + ivec2(centre);
  float edge = texelFetch(u_edge, p, 0).r;
  vec4 all_quads = esm_decode(vec2(edge, texelFetch(u_edge_depth, p, 0).r));
  outward = has_quad(all_quads) ? esm_edge_outward(edge) : vec2(0.0);
  behind = has_quad(all_quads) && behind_edge(all_quads, outward, centre, r);
  if (!u_nearest_edge || !has_quad(all_quads) || behind) return all_quads;
  // Only an edge nearer than the farthest: the same one (its depth rounded up) has been judged.
  vec4 nearest_edge = esm_decode_near(texelFetch(u_edge_near, p, 0).r);
  behind = has_quad(nearest_edge) && nearest_edge.b < all_quads.b &&
           behind_edge(vec4(nearest_edge.rgb, NEAREST_EDGE_ONLY), outward, centre, r);
  return behind ? vec4(nearest_edge.rgb, NEAREST_EDGE_ONLY) : all_quads;
}

// Lit-ness of a texel for a receiver at depth z behind all the footprint's edges: a quad's, unless
// the texel lies outside its edge and an occluder there is in front of the receiver (that
// occluder is not the edge's own surface); without a quad, the plain test's 0 or 1.
float litness(vec4 texel, float depth, float z) {
  bool occluded = z > depth;
  if (!has_quad(texel)) return occluded ? 0.0 : 1.0;
  float l = 1.0 - texel.r;
  return occluded && l >= edge_litness() ? 0.0 : l;
}

// The texel's quad puts it deep inside an occluder, yet the plain test finds nothing in front of
// the receiver there. One edge cannot say that: it is the inner band of an object thinner than
// the band, or of a neighbouring silhouette, lying over lit ground (dense silhouettes, where MAX
// kept an inside over the outside of the edge that passes there).
bool contradicts(vec4 texel, float depth, float z) {
  return has_quad(texel) && 1.0 - texel.r <= deep_inside_litness() && z <= depth;
}

// Edge lines (edge_lines): each texel holds its edge as a line (its signed distance and outward
// direction, esm_common.glsl), and the receiver's signed distance from the silhouette is taken
// from the lines at the receiver instead of interpolating the texels' distances. Bilinear
// interpolation is exact for one straight edge across the footprint; where the footprint's texels
// hold different edges (corners, the sub-texel steps of a tessellated curve, bars and neighbours a
// few texels apart) it blends distances to different lines and bends the boundary. The receiver's
// nearest texel's line decides (else the line nearest the receiver), combined with each other
// texel's differing line as a corner: where each line's point nearest its texel lies inside the
// other line, a convex corner (the intersection of the two insides: the larger distance), else the
// union (the smaller), which keeps crossing shadows and reflex corners filled (a corner left to the
// first line alone lit holes where pipes cross: crossed_pipes_test.cpp). Edge error at 512^2,
// 1080p, H200, with the contradiction rule below: poles 0.0175 -> 0.0074, showcase 0.0352 ->
// 0.0221, FlightHelmet 0.0630 -> 0.0549, 0.42-1.00x on 11 scenes (docs/results/esm.md, "edge lines").
// Written with four structs and no arrays: indexing arrays of the footprint's texels cost the whole
// mask 0.007-0.013 ms of occupancy on an H200, lines or not (same section).
// A texel's edge line, `centre` its offset in the footprint (texels), at the receiver f.
struct EdgeLine {
  bool valid;
  float distance;  // at the texel's centre (texels, > 0 outside)
  vec2 outward;
  vec2 centre;
  float at;        // at the receiver
};

EdgeLine edge_line(vec4 texel, vec2 outward, bool valid, vec2 centre, vec2 f) {
  EdgeLine e;
  e.valid = valid;
  e.distance = texel.g;
  e.outward = valid ? outward : vec2(0.0);
  e.centre = centre;
  e.at = e.distance + dot(f - centre, e.outward);
  return e;
}

// The line nearer the receiver (the first on a tie), of those that are valid.
EdgeLine nearer(EdgeLine a, EdgeLine b) { return !a.valid || (b.valid && abs(b.at) < abs(a.at)) ? b : a; }

// `line`, combined with the decided line `first` as a corner (above) into d.
void corner(EdgeLine first, EdgeLine line, inout float d, inout vec2 d_outward) {
  // The same line (a straight edge across the footprint, or first itself), to well within the ramp of a pixel.
  if (!line.valid || abs(line.at - first.at) <= 0.02) return;
  vec2 foot = first.centre - first.distance * first.outward;  // the line's point nearest its texel
  vec2 line_foot = line.centre - line.distance * line.outward;
  bool convex = line.distance + dot(foot - line.centre, line.outward) < 0.0 &&
                first.distance + dot(line_foot - first.centre, first.outward) < 0.0;
  if (convex ? line.at > d : line.at < d) {
    d = line.at;
    d_outward = line.outward;
  }
}

// The receiver's signed distance from the silhouette and its direction from the footprint's lines;
// false when no texel gives one. The nearest texel is the one of f's quadrant.
bool edge_line_distance(EdgeLine e00, EdgeLine e10, EdgeLine e01, EdgeLine e11, vec2 f, out float d, out vec2 d_outward) {
  EdgeLine first = f.y >= 0.5 ? (f.x >= 0.5 ? e11 : e01) : (f.x >= 0.5 ? e10 : e00);
  if (!first.valid) first = nearer(nearer(e00, e10), nearer(e01, e11));
  if (!first.valid) return false;
  d = first.at;
  d_outward = first.outward;
  corner(first, e00, d, d_outward);
  corner(first, e10, d, d_outward);
  corner(first, e01, d, d_outward);
  corner(first, e11, d, d_outward);
  return true;
}

float visibility(ivec2 pixel, vec3 world, vec3 normal) {
  // Cascades: the one the other techniques read this receiver in (none holds it: the last, whose
  // coordinate is then outside its tile, lit).
  int face = kCascades > 1 ? min(cascade_of(world), kCascades - 1) : esm_face(world);
  vec4 c = esm_map_coord(face, world);
  if (c.w == 0.0 || c.z < 0.0 || c.z > 1.0) return 1.0;  // outside the map: lit
  float z = esm_biased_depth(c.z, u_depth_bias);
  // The 2x2 texels around the receiver, clamped to its face's tile.
  vec4 rect = u_face_rect[face];
  vec2 st = c.xy - 0.5;
  ivec2 i0 = clamp(ivec2(floor(st)), ivec2(rect.xy), ivec2(rect.xy + rect.z) - 2);
  vec2 f = clamp(st - vec2(i0), 0.0, 1.0);
  // Point filtering: the nearest of the four.
  ivec2 nearest = i0 + ivec2(f.x >= 0.5 ? 1 : 0, f.y >= 0.5 ? 1 : 0);
  bool a = z > texelFetch(u_shadow_map, nearest, 0).r;
  // Away from silhouettes (most receivers) no texel of the footprint has a quad: one gather of
  // the mask channel says so, and the answer is the plain test's.
  vec4 marked = textureGather(u_edge, (vec2(i0) + 1.0) / vec2(textureSize(u_edge, 0)), 0);
  if (all(lessThan(marked, vec4(QUAD_MARK)))) return a ? 0.0 : 1.0;
  // The receiver's tangent plane in the map: where the neighbouring pixels' camera rays meet it
  // (texels and window depth per pixel along x and y).
  vec2 px = vec2(pixel) + 0.5;
  vec3 cx = esm_map_coord(face, on_plane(px + vec2(1.0, 0.0), world, normal)).xyz - c.xyz;
  vec3 cy = esm_map_coord(face, on_plane(px + vec2(0.0, 1.0), world, normal)).xyz - c.xyz;
  // Behind an edge by more than the receiver's own surface changes depth over edge_bias texels, and
  // with edge_plane by its plane at the edge (behind_edge): a surface running into its own
  // silhouette edge (an open sheet seen from its lit side, the lit facet next to a sharp edge) is
  // not shadowed by that edge.
  vec2 dz = receiver_gradient(cx, cy);
  Receiver r = Receiver(z, dz, length(dz) * u_edge_bias_texels, f);
  vec2 o00, o10, o01, o11;   // their edge lines' directions
  bool b00, b10, b01, b11;   // behind their edges
  vec4 t00 = map_texel(i0, vec2(0.0, 0.0), r, o00, b00), t10 = map_texel(i0, vec2(1.0, 0.0), r, o10, b10);
  vec4 t01 = map_texel(i0, vec2(0.0, 1.0), r, o01, b01), t11 = map_texel(i0, vec2(1.0, 1.0), r, o11, b11);
  float d00 = texelFetch(u_shadow_map, i0, 0).r, d10 = texelFetch(u_shadow_map, i0 + ivec2(1, 0), 0).r;
  float d01 = texelFetch(u_shadow_map, i0 + ivec2(0, 1), 0).r, d11 = texelFetch(u_shadow_map, i0 + ivec2(1, 1), 0).r;
  vec4 tn = nearest.y > i0.y ? (nearest.x > i0.x ? t11 : t01) : (nearest.x > i0.x ? t10 : t00);
  // b: the footprint has quads and the receiver is behind an edge of each (map_texel: the farthest,
  // else the nearest). Where it is in front of both, the edge distances say nothing reliable about
  // it: plain shadow mapping (the paper: near overlaps the method "behaves almost like standard
  // shadow mapping").
  int quads = int(has_quad(t00)) + int(has_quad(t10)) + int(has_quad(t01)) + int(has_quad(t11));
  int behind = int(b00) + int(b10) + int(b01) + int(b11);
  bool b = quads > 0 && behind == quads;
  if (!b) return a ? 0.0 : 1.0;
  // Occluded at the nearest texel: only its own edge's inside may lighten it (sub-texel).
  bool own_edge = has_quad(tn) && 1.0 - tn.r < edge_litness();
  if (a && !own_edge) return 0.0;
  // Edge data that contradicts the depth map anywhere in the footprint: the plain answer, so esm is
  // never worse than the map it extends. Measured edge error on showcase's pickets (llvmpipe,
  // 384x288, tests/esm/edge_error_test.cpp), esm / plain: 256^2 0.0871 / 0.0858 before, 0.0755
  // with this rule; 512^2 0.0355 / 0.0502 before, 0.0373. Per texel instead (the texel's plain
  // 0 or 1 in the interpolation) gave 0.0763 and 0.0422. With edge lines a contradicting texel
  // gives no line, and the plain answer is kept for footprints where no texel gives one: edge
  // error at 512^2, 1080p, llvmpipe 0.89 (Fox) to 1.00x the whole-footprint rule's, showcase at
  // 256^2 0.132 -> 0.100 (docs/results/esm.md, "edge lines").
  bvec4 contradiction = bvec4(contradicts(t00, d00, z), contradicts(t10, d10, z), contradicts(t01, d01, z),
                              contradicts(t11, d11, z));
  bool contradicted = any(contradiction);
  if (contradicted && !u_edge_lines) return a ? 0.0 : 1.0;
  float l00 = litness(t00, d00, z), l10 = litness(t10, d10, z), l01 = litness(t01, d01, z), l11 = litness(t11, d11, z);
  float boundary = distance_litness(u_boundary_shift);
  // All four texels inside the boundary, and the receiver occluded at its nearest texel: so is it
  // inside. (Texels deeper than the band read 0 from the plain test, not the linear lit-ness, so
  // the ramp below, extrapolated from the local gradient, could call receivers deep in the shadow
  // partly lit. Outside, the band is wider.) Not occluded there, the receiver lies where the
  // texels' edges meet within a texel (slats, leaflets, a mask's frame lines under a texel wide)
  // and their lines decide: edge error at 512^2, 1080p, llvmpipe, AlphaBlendModeTest 0.0399 ->
  // 0.0332, palms 0.0780 -> 0.0762, the rest within 1%; avenue at 384x288 0.1663 -> 0.1567, below
  // the plain map's 0.1649 (docs/results/esm.md, "the receiver's plane at the edge").
  if (a && all(lessThan(vec4(l00, l10, l01, l11), vec4(boundary)))) return 0.0;
  if (u_edge_lines) {
    // A texel gives its line when map_texel kept its own quads (not the nearest edge alone: no
    // distance) and it does not contradict the depth map.
    EdgeLine e00 = edge_line(t00, o00, t00.a == QUAD_TEXEL && !contradiction.x, vec2(0.0, 0.0), f);
    EdgeLine e10 = edge_line(t10, o10, t10.a == QUAD_TEXEL && !contradiction.y, vec2(1.0, 0.0), f);
    EdgeLine e01 = edge_line(t01, o01, t01.a == QUAD_TEXEL && !contradiction.z, vec2(0.0, 1.0), f);
    EdgeLine e11 = edge_line(t11, o11, t11.a == QUAD_TEXEL && !contradiction.w, vec2(1.0, 1.0), f);
    float d;
    vec2 d_outward;
    if (edge_line_distance(e00, e10, e01, e11, f, d, d_outward)) {
      if (u_aa_width <= 0.0) return d >= u_boundary_shift ? 1.0 : 0.0;
      float per_pixel = length(vec2(dot(d_outward, cx.xy), dot(d_outward, cy.xy)));  // |d distance / d pixel|
      return clamp(0.5 + (d - u_boundary_shift) / max(per_pixel, 1e-6) / u_aa_width, 0.0, 1.0);
    }
    if (contradicted) return a ? 0.0 : 1.0;
  }
  // Bilinear lit-ness and its gradient (per texel).
  float l = mix(mix(l00, l10, f.x), mix(l01, l11, f.x), f.y);
  vec2 g = vec2(mix(l10 - l00, l11 - l01, f.y), mix(l01 - l00, l11 - l10, f.x));
  if (u_aa_width <= 0.0) return l >= boundary ? 1.0 : 0.0;
  // The ramp is u_aa_width pixels wide on screen: the edge's coverage of the pixel.
  float per_pixel = length(vec2(dot(g, cx.xy), dot(g, cy.xy)));  // |d lit-ness / d pixel|
  float distance_px = (l - boundary) / max(per_pixel, 1e-6);
  return clamp(0.5 + distance_px / u_aa_width, 0.0, 1.0);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  float lit = 1.0;
  if (pos.w > 0.0) {
    vec3 n = gbuffer_normal(u_normal, p);
    lit = faces_away_from_light(pos.xyz, n) ? 0.0 : visibility(p, pos.xyz, normalize(n));
  }
  imageStore(u_mask, p, vec4(lit));
}
