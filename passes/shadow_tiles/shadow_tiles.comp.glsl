#version 450 core
// Screen-tile classifier: one work group per SCREEN_TILE x SCREEN_TILE tile, which it calls
//   lit      when every pixel's filter gives exactly 1 (background, outside the map, or a
//            receiver none of whose taps can find a blocker),
//   umbra    when every pixel's filter gives exactly 0 (facing away from the light, or a receiver
//            every tap of which finds only blockers), or
//   penumbra otherwise, appended to the tile list the filters dispatch over.
//
// Conservative by construction. A filter's taps lie within `reach` R (shadow-map UV, from the
// pass's parameters) of the receiver's coordinate c; a tap at offset o compares against the
// receiver plane, ref(o) = z + dot(o, g) - L1(g) texel - bias (receiver_depth_at, Isidoro 2006;
// L1(g) = |g.x| + |g.y|), and reads texels whose centres lie less than a texel from it. So texel t
// is only read when |t - c| <= rho = R + 1.25 texels (the quarter for the hardware's rounding) and
// is compared with references in [z + dot(t - c, g) - 2 L1(g) texel - bias, z + dot(t - c, g) - bias].
// One plane bounds every receiver r of the tile: with the gradient G of one of them,
//   z_r + dot(t - c_r, g_r) <= E + dot(t, G),  E = max_r z_r - dot(c_r, G) + L1(g_r - G) rho,
//   z_r + dot(t - c_r, g_r) >= F + dot(t, G),  F = min_r z_r - dot(c_r, G) - L1(g_r - G) rho,
// (exact for a tile on one flat surface, where g_r = G). The map is a plane per block
// (shadow_planes.comp.glsl: gradient h, residuals in [lo, hi] about the block centre m, half size
// s). Over each block that the tile's read region touches, with slack = |G.x - h.x| s.x + |G.y - h.y| s.y:
//   no texel is a blocker of any tap   if lo >= E - bias + dot(m, G) + slack,
//                                      and with cleared texels (depth 1) the largest reference <= 1;
//   every texel blocks every tap       if hi < F - bias - 2 max L1(g_r) texel + dot(m, G) - slack,
//                                      never with cleared texels.
// The group reads the blocks of the read region together; regions wider than kMaxBlocks blocks each
// way are not classified (penumbra): size the planes (shadow/N) so the reach spans a few blocks.
// A point light's six faces (shadow_common.glsl) are not classified either.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "common/receiver_plane.glsl"
#include "shadow_tiles/tile_class.glsl"

layout(r8, binding = 0) uniform writeonly image2D u_tile_class;
uniform sampler2D u_depth;       // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;      // gbuffer_normal: octahedral
uniform sampler2D u_planes;      // shadow_planes: gradient (rg), residual min (b), max (a)
uniform float u_reach_uv;        // largest tap offset from a receiver, shadow-map UV
uniform float u_depth_bias;      // the filters' constant bias, window depth

const int kMaxBlocks = 64;
const float kCleared = 1e30;  // shadow_planes.comp.glsl
// Rounding between this pass and the filters (the same formulas, compiled apart) is far below this.
const float kMargin = 4e-6;

// Floats as uints that order like the floats, for shared atomics (measured faster here than a
// shared-memory tree: 116 against 167 us at 3840x2160 on an H100).
uint ordered(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float unordered(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7fffffffu : ~u); }

shared bool s_all_lit, s_all_umbra;
shared uint s_first;                 // local index of the first receiver: its gradient is G
shared vec2 s_gradient[SCREEN_TILE * SCREEN_TILE];
shared uint s_e, s_f, s_largest_ref, s_fractional;  // ordered floats
shared uvec2 s_read_lo, s_read_hi;   // the read region, in blocks

void main() {
  uint i = gl_LocalInvocationIndex;
  if (i == 0u) {
    s_all_lit = s_all_umbra = true;
    s_first = 0xffffffffu;
    s_e = s_largest_ref = s_fractional = ordered(-1e30);
    s_f = ordered(1e30);
    s_read_lo = uvec2(0xffffffffu);
    s_read_hi = uvec2(0u);
  }
  barrier();

  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 blocks = textureSize(u_planes, 0);
  vec2 block_uv = 1.0 / vec2(blocks);  // a block's extent in UV (the last one may be cut short)
  float rho = u_reach_uv + 1.25 * u_shadow_texel;
  Receiver r;
  bool receiver = false;
  if (all(lessThan(p, textureSize(u_depth, 0)))) {
    int kind = receiver_at(u_depth, u_normal, p, r);
    if (kind == RECEIVER_FACES_AWAY) {
      s_all_lit = false;   // 0
    } else if (kind == RECEIVER_LIT) {
      s_all_umbra = false;  // 1
    } else {
      add_receiver_plane(u_depth, p, r);
      receiver = true;
      s_gradient[i] = r.dz_duv;
      atomicMin(s_first, i);
    }
  }
  barrier();

  // A point light's six faces, or cascades: one plane per block cannot bound taps that may read
  // another face's tile, or a cascade of another texel size, so a tile with a receiver to filter
  // is penumbra.
  if (s_first == 0xffffffffu || kTiledMap) {  // no receiver: the kinds above decide
    if (i == 0u) {
      if (s_first != 0xffffffffu) s_all_lit = s_all_umbra = false;
      float tile_class = s_all_lit ? TILE_LIT : s_all_umbra ? TILE_UMBRA : TILE_PENUMBRA;
      imageStore(u_tile_class, ivec2(gl_WorkGroupID.xy), vec4(tile_class));
      if (tile_class == TILE_PENUMBRA) tile_list_append(gl_WorkGroupID.xy);
    }
    return;
  }
  vec2 G = s_gradient[s_first];
  if (receiver) {
    vec2 g = r.dz_duv;
    float l1 = abs(g.x) + abs(g.y);
    vec2 parted = abs(g - G) * rho;
    float base = r.coord.z - dot(r.coord.xy, G);
    atomicMax(s_e, ordered(base + parted.x + parted.y));
    atomicMin(s_f, ordered(base - parted.x - parted.y));
    atomicMax(s_largest_ref, ordered(r.coord.z - u_depth_bias + l1 * (u_reach_uv - u_shadow_texel)));
    atomicMax(s_fractional, ordered(2.0 * l1 * u_shadow_texel));
    uvec2 lo = uvec2(clamp(ivec2(floor(max(r.coord.xy - rho, vec2(0.0)) / block_uv)), ivec2(0), blocks - 1));
    uvec2 hi = uvec2(clamp(ivec2(floor(min(r.coord.xy + rho, vec2(1.0)) / block_uv)), ivec2(0), blocks - 1));
    atomicMin(s_read_lo.x, lo.x);
    atomicMin(s_read_lo.y, lo.y);
    atomicMax(s_read_hi.x, hi.x);
    atomicMax(s_read_hi.y, hi.y);
  }
  barrier();

  ivec2 b0 = ivec2(s_read_lo), extent = ivec2(s_read_hi) - b0 + 1;
  if (any(greaterThan(extent, ivec2(kMaxBlocks)))) {
    if (i == 0u) s_all_lit = s_all_umbra = false;
  } else {
    float e = unordered(s_e) - u_depth_bias, f = unordered(s_f) - u_depth_bias - unordered(s_fractional);
    bool cleared_ok = unordered(s_largest_ref) + kMargin <= 1.0;
    bool lit = true, umbra = true;
    for (int k = int(i); k < extent.x * extent.y; k += SCREEN_TILE * SCREEN_TILE) {
      ivec2 b = b0 + ivec2(k % extent.x, k / extent.x);
      vec4 plane = texelFetch(u_planes, b, 0);  // h = plane.rg about the block centre m
      vec2 lo_uv = vec2(b) * block_uv;
      vec2 hi_uv = min(lo_uv + block_uv, vec2(1.0));
      vec2 m = 0.5 * (lo_uv + hi_uv), half_size = 0.5 * (hi_uv - lo_uv);
      vec2 parted = abs(G - plane.rg) * half_size;
      float slack = parted.x + parted.y;
      float offset = dot(m, G);
      bool cleared = plane.a >= kCleared;
      lit = lit && plane.b >= e + offset + slack + kMargin && (!cleared || cleared_ok);
      umbra = umbra && !cleared && plane.a < f + offset - slack - kMargin;
    }
    if (!lit) s_all_lit = false;
    if (!umbra) s_all_umbra = false;
  }
  barrier();

  if (i != 0u) return;
  float tile_class = s_all_lit ? TILE_LIT : s_all_umbra ? TILE_UMBRA : TILE_PENUMBRA;
  imageStore(u_tile_class, ivec2(gl_WorkGroupID.xy), vec4(tile_class));
  if (tile_class == TILE_PENUMBRA) tile_list_append(gl_WorkGroupID.xy);
}
