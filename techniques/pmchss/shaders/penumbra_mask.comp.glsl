#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Penumbra mask (Sterna 2018, section 2.2): the blocker search of Listing 3 run at a reduced
// resolution (screen/4 or screen/2), then -- in the same dispatch -- the optional 7x7 max filter
// and the separable 7x7 Gaussian blur (sigma 3) the paper applies to the mask.
//
// Why one dispatch: at screen/4 the search and each blur axis are tiny grids whose cost on a
// large GPU is mostly fixed per dispatch. Measured on an H100 at 1080p (docs/results/pmchss.md):
// search + blur x + blur y as three dispatches 21.4 + 8.2 + 8.7 us, this one dispatch 24.8 us.
//
// A 32 x 32 workgroup (1024 invocations, the GL minimum for MAX_COMPUTE_WORK_GROUP_INVOCATIONS)
// searches a 32 x 32 region of the mask, one search per invocation, into shared memory, runs the
// filter stages there and writes the TILE x TILE block inside the halo (RADIUS per stage):
// TILE = 32, 26 or 20, i.e. 1.0x, 1.5x or 2.6x searches per written texel. Each stage reads its
// input at the clamped image coordinate (the separable passes' clamp-to-edge), which always lies
// in the part of the region the previous stage computed: clamping moves a coordinate towards the
// block, and every stage covers the block. The pass sets TILE and dispatches one workgroup per
// block (penumbra_mask_pass.cpp, PassContext::dispatch_tiles).
//
// Defines: BLUR (0/1), MAX_FILTER (0/1); OUTPUT_BLOCKER_DEPTH turns the search into the debug
// view of the average blocker distance over the far plane (1 = no blocker) instead of the penumbra.
#define REGION 32
layout(local_size_x = REGION, local_size_y = REGION) in;
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "common/receiver_plane.glsl"
#define PENUMBRA_MASK_SEARCH 1
#include "pmchss_common.glsl"

const int kRadius = 3;  // 7x7 max filter and 7x7 Gaussian (section 2.2)
const int kHalo = kRadius * (BLUR + MAX_FILTER);
const int kRegion = REGION;  // TILE + 2 * kHalo, TILE set by the pass
const int kRegionTexels = kRegion * kRegion;
const int kThreads = kRegionTexels;

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_shadow_map;  // raw window depth, nearest (Listing 3's pointClampSampler)
uniform int u_default_one;       // section 2.2: write 1 instead of 0 where no blocker is found
uniform float u_blur_sigma;      // mask texels (section 2.2: 3)

// Two region-sized buffers the stages ping-pong between (offset 0 and kRegionTexels).
shared float s_region[2 * kRegionTexels];

float search(ivec2 p, ivec2 mask_size, ivec2 full_size) {
  ivec2 scale = max(full_size / mask_size, ivec2(1));
  ivec2 full = min(p * scale + scale / 2, full_size - 1);
  // "Lit" everywhere nothing is found: background, outside the light frustum, no blocker.
  float value = u_default_one == 1 ? 1.0 : 0.0;
#ifdef OUTPUT_BLOCKER_DEPTH
  value = 1.0;
#endif
  vec4 pos = gbuffer_position(u_depth, full);
  if (pos.w <= 0.0) return value;
  if (!pmchss_in_shadow_frustum(shadow_coord(pos.xyz))) return value;
  Receiver r = pmchss_receiver(u_depth, u_normal, full, pos.xyz);
  // Noise on the mask's own pixel grid (section 1.2's IGN, whatever the shadow mask's
  // rotation_noise): the blur averages the searches of neighbouring mask texels, which it can only
  // do for independent rotations. Surface cells shared by several mask texels measured worse
  // (showcase penumbra RMSE +4%, docs/results/cascades.md); the mask lies on the screen anyway.
  float phi = noise_rotation(vec2(p) + 0.5);
  float blocker;
  float count = pmchss_blocker_search(u_shadow_map, r, BLOCKER_SAMPLES, phi, blocker);
#ifdef OUTPUT_BLOCKER_DEPTH
  return blocker / u_light_far;
#else
  return count > 0.0 ? pmchss_penumbra_from_blocker(receiver_light_distance(r), blocker) : value;
#endif
}

// Index into a region buffer of the texel at image coordinate g, clamped to the image.
int region_index(ivec2 g, ivec2 origin, ivec2 size) {
  ivec2 r = clamp(g, ivec2(0), size - 1) - origin;
  return r.y * kRegion + r.x;
}

bool inside(ivec2 g, ivec2 size) { return all(greaterThanEqual(g, ivec2(0))) && all(lessThan(g, size)); }

// One filter axis from buffer `src` to buffer `dst` over region texels [lo, hi); texels outside
// the image are skipped (nothing reads them). gaussian: normalised exp(-t^2 / 2 sigma^2) weights,
// as the separable pass computes them; otherwise max.
void filter_stage(int src, int dst, bool gaussian, ivec2 axis, ivec2 lo, ivec2 hi, ivec2 origin,
                  ivec2 size) {
  ivec2 extent = hi - lo;
  for (int i = int(gl_LocalInvocationIndex); i < extent.x * extent.y; i += kThreads) {
    ivec2 r = lo + ivec2(i % extent.x, i / extent.x);
    ivec2 g = origin + r;
    if (!inside(g, size)) continue;
    float acc = gaussian ? 0.0 : s_region[src + region_index(g, origin, size)];
    float weights = 0.0;
    for (int t = -kRadius; t <= kRadius; ++t) {
      float v = s_region[src + region_index(g + t * axis, origin, size)];
      if (gaussian) {
        float w = exp(-float(t * t) / (2.0 * u_blur_sigma * u_blur_sigma));
        acc += w * v;
        weights += w;
      } else {
        acc = max(acc, v);
      }
    }
    s_region[dst + r.y * kRegion + r.x] = gaussian ? acc / weights : acc;
  }
  memoryBarrierShared();
  barrier();
}

// Both axes of one separable filter: x then y, each shrinking the computed part of the region by
// the radius along its axis; the result is back in buffer `src`.
void filter_2d(int src, int dst, bool gaussian, inout ivec2 lo, inout ivec2 hi, ivec2 origin, ivec2 size) {
  lo.x += kRadius; hi.x -= kRadius;
  filter_stage(src, dst, gaussian, ivec2(1, 0), lo, hi, origin, size);
  lo.y += kRadius; hi.y -= kRadius;
  filter_stage(dst, src, gaussian, ivec2(0, 1), lo, hi, origin, size);
}

void main() {
  ivec2 size = imageSize(u_mask);
  ivec2 full_size = textureSize(u_depth, 0);
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * TILE - kHalo;

  ivec2 searched = ivec2(gl_LocalInvocationID.xy);  // this invocation's region texel
  if (inside(origin + searched, size))
    s_region[int(gl_LocalInvocationIndex)] = search(origin + searched, size, full_size);
  memoryBarrierShared();
  barrier();

  int src = 0, dst = kRegionTexels;
  ivec2 lo = ivec2(0), hi = ivec2(kRegion);
#if MAX_FILTER
  // Section 2.2's max filter before the blur (the paper recommends against it; kept selectable).
  filter_2d(src, dst, false, lo, hi, origin, size);
#endif
#if BLUR
  filter_2d(src, dst, true, lo, hi, origin, size);
#endif

  ivec2 local = searched - kHalo;  // position in the block
  if (all(greaterThanEqual(local, ivec2(0))) && all(lessThan(local, ivec2(TILE))) && inside(origin + searched, size))
    imageStore(u_mask, origin + searched, vec4(s_region[src + int(gl_LocalInvocationIndex)]));
}
