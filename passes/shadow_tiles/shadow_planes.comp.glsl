#version 450 core
// The shadow map as a plane per block: each output texel covers a block of ceil(map / output)
// texels each way (8 x 8 at shadow/8); the plane d = a + dot(t - c, g) is fitted through the
// block's depths (least squares, c the block centre) and the range of the residuals
// d(t) - dot(t - c, g) kept:
//   r, g = the plane's gradient d(window depth)/d(uv);  b = the smallest residual;  a = the largest,
//   or kCleared when the block has texels nothing was drawn into (depth 1: the far plane).
// On a surface seen by the light the residuals are ~0 at any slope, so the classifier
// (shadow_tiles.comp.glsl) can bound a receiver's comparisons over a whole block with the
// receiver's own plane (Isidoro 2006) without the block's slope counting as a blocker; a caster in
// the block widens the range. Cleared texels are left out of the fit (a caster's outline against
// them would tilt it).
//
// BLOCK_THREADS invocations share a block (the pass dispatches output height x the work group's
// height), each reading row pairs k, k + BLOCK_THREADS, ... of it two columns at a time, with
// textureGather; their sums meet in shared memory. The reads bound the pass: a texelFetch per
// texel, twice, took 41.7 us at 2048^2 on an H200 whether one invocation walked a whole block
// (65,536 invocations) or eight shared it; gathers with 1, 2, 4 or 8 invocations a block took
// 35.8, 25.4, 20.1 and 27.7 us (docs/results/tiles.md); a work group per block with shared-memory
// trees took 381 us on an H100.
#define GROUP_BLOCKS 8
#define BLOCK_THREADS 4
layout(local_size_x = GROUP_BLOCKS, local_size_y = BLOCK_THREADS) in;

layout(rgba32f, binding = 0) uniform writeonly image2D u_planes;
uniform sampler2D u_shadow_map;  // raw depth: no comparison, clamped at the edges

// Texels t, t + (1, 0), t + (0, 1), t + (1, 1): one gather whose footprint's lower-left texel is t.
vec4 texel_quad(ivec2 t, vec2 map_size) {
  vec4 g = textureGather(u_shadow_map, (vec2(t) + 1.0) / map_size);
  return vec4(g.w, g.z, g.x, g.y);
}
const ivec2 kQuad[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 1));

const float kCleared = 1e30;
const int kMoments = 9;  // n, x, y, xx, yy, xy, d, xd, yd (x, y: texels from the centre)

shared float s_moments[GROUP_BLOCKS][BLOCK_THREADS][kMoments];
shared vec2 s_slope[GROUP_BLOCKS];
shared vec2 s_range[GROUP_BLOCKS][BLOCK_THREADS];  // residual min, max over the invocation's texels
shared bool s_cleared[GROUP_BLOCKS][BLOCK_THREADS];

// The block's drawn texels, walked by this invocation: its row pairs, two columns at a time. The
// first walk (FIT) sums the moments of the least-squares fit, the second the residuals' range
// about `slope`.
const int FIT = 0, RESIDUALS = 1;
void walk_block(int walk, ivec2 first, ivec2 last, vec2 centre, vec2 slope, inout float m[kMoments],
                inout bool cleared, inout vec2 range) {
  uint thread = gl_LocalInvocationID.y;
  ivec2 map_size = textureSize(u_shadow_map, 0);
  for (int y = first.y + 2 * int(thread); y < last.y; y += 2 * BLOCK_THREADS)
    for (int x = first.x; x < last.x; x += 2) {
      vec4 quad = texel_quad(ivec2(x, y), vec2(map_size));
      for (int k = 0; k < 4; ++k) {
        ivec2 t = ivec2(x, y) + kQuad[k];
        if (any(greaterThanEqual(t, last))) continue;  // past the block: the next block's, or clamped
        float d = quad[k];
        if (d >= 1.0) {
          cleared = true;
          continue;
        }
        vec2 o = vec2(t) + 0.5 - centre;
        if (walk == RESIDUALS) {
          float residual = d - dot(o, slope);
          range = vec2(min(range.x, residual), max(range.y, residual));
          continue;
        }
        m[0] += 1.0;
        m[1] += o.x;
        m[2] += o.y;
        m[3] += o.x * o.x;
        m[4] += o.y * o.y;
        m[5] += o.x * o.y;
        m[6] += d;
        m[7] += o.x * d;
        m[8] += o.y * d;
      }
    }
}

void main() {
  uint slot = gl_LocalInvocationID.x, thread = gl_LocalInvocationID.y;
  ivec2 q = ivec2(gl_WorkGroupID.x * GROUP_BLOCKS + slot, gl_WorkGroupID.y);
  ivec2 out_size = imageSize(u_planes);
  bool inside = all(lessThan(q, out_size));  // outside blocks still reach every barrier
  ivec2 map_size = textureSize(u_shadow_map, 0);
  ivec2 block = (map_size + out_size - 1) / out_size;
  ivec2 first = min(q * block, map_size - 1);
  ivec2 last = min(first + block, map_size);
  vec2 centre = 0.5 * vec2(first + last);  // texel space, texel i's centre at i + 0.5

  float m[kMoments];
  for (int k = 0; k < kMoments; ++k) m[k] = 0.0;
  bool cleared = false;
  vec2 range = vec2(kCleared, -kCleared);  // residual min, max
  if (inside) walk_block(FIT, first, last, centre, vec2(0.0), m, cleared, range);
  for (int k = 0; k < kMoments; ++k) s_moments[slot][thread][k] = m[k];
  s_cleared[slot][thread] = cleared;
  barrier();

  // Least squares from the centred second moments: exact for a plane, whatever subset of the
  // block it covers (the residual range below is exact for whatever plane comes out).
  if (thread == 0u) {
    for (uint r = 1u; r < BLOCK_THREADS; ++r)
      for (int k = 0; k < kMoments; ++k) m[k] += s_moments[slot][r][k];
    vec2 slope = vec2(0.0);  // per texel
    float n = m[0];
    if (n >= 3.0) {
      vec2 mean_o = vec2(m[1], m[2]) / n;
      float mean_d = m[6] / n;
      float cxx = m[3] / n - mean_o.x * mean_o.x, cyy = m[4] / n - mean_o.y * mean_o.y;
      float cxy = m[5] / n - mean_o.x * mean_o.y;
      float cxd = m[7] / n - mean_o.x * mean_d, cyd = m[8] / n - mean_o.y * mean_d;
      float det = cxx * cyy - cxy * cxy;
      if (det > 1e-6 * max(cxx * cyy, 1e-12)) slope = vec2(cyy * cxd - cxy * cyd, cxx * cyd - cxy * cxd) / det;
    }
    s_slope[slot] = slope;
  }
  barrier();

  vec2 slope = s_slope[slot];
  if (inside) walk_block(RESIDUALS, first, last, centre, slope, m, cleared, range);
  s_range[slot][thread] = range;
  barrier();

  if (thread != 0u || !inside) return;
  for (uint r = 1u; r < BLOCK_THREADS; ++r) {
    range = vec2(min(range.x, s_range[slot][r].x), max(range.y, s_range[slot][r].y));
    cleared = cleared || s_cleared[slot][r];
  }
  imageStore(u_planes, q, vec4(slope * vec2(map_size), range.x, cleared ? kCleared : range.y));
}
