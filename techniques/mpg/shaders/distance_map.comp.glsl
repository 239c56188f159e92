#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Pass 2 (Cherry & Kooima, sections 3.1-3.2): the distance map. Per pixel, the hard shadow S
// (SHADOW_TEST: the paper's bit from the nearest texel, or the bilinear weight of the 2x2 texels;
// hard_shadow() below) and the filter control D from the occluder distance d_r - d_b
// (light-space distance of the receiver minus that of the blocking texels, world units,
// light_distance()).
//
// MAPPING (a define, from the `mapping` parameter):
//   0 paper:    D = (occluder distance / light depth range)^Dp * Dm (section 3.2). The paper's
//               distance is in scene units, so its Dp/Dm fit one scene scale; dividing by the
//               light frustum's depth range (far - near, world units) makes the distance a
//               fraction in [0, 1] of the depth the shadow map spans: the same Dp/Dm mean the
//               same thing for a 1 m toy and a 100 m court.
//   1 physical: the penumbra width of PCSS (Fernando 2005; the paper's section 6 proposes it),
//               w = (d_r - d_b) * light size / d_b (spot) or (d_r - d_b) * light size / D_sun
//               (directional: the sun-like light of scene/light.h), world units across the
//               light direction, times light_size_scale. A disk light of diameter w throws an
//               edge ramp whose spread (standard deviation) is w / 4 (the 1-D marginal of a
//               uniform disk). In pixels: spread_px = (w / 4) * g, g the pixels per world unit of
//               the receiver's penumbra footprint (kernel_shape.glsl: the geometric mean of its
//               two screen axes; with `anisotropic` off, focal_px / z for a receiver facing the
//               camera at view depth z). D is the filter setting whose round kernel has that
//               spread:
//                 pcf       box of size s has sd s / sqrt(12):           D = sqrt(12) spread_px
//                 gaussian  sigma = s / 3 truncated to +-s/2, sd 0.2477 s: D = spread_px / 0.2477
//                 multipass the (fractional) number of passes whose summed variance (CPU,
//                           multipass_kernel.cpp, u_pass_variance) reaches spread_px^2
//
// KERNEL SHAPE (second output, every receiver pixel; kernel_shape.glsl): the symmetric 2x2
// matrix A (det 1) that maps the round kernel onto the receiver's penumbra footprint on screen
// (identity when `anisotropic` is off) and the receiver plane's view-depth gradient per pixel,
// written as (A11, A12, dz/dx, dz/dy); background (1, 0, 0, 0).
//
// SHADOW_TEST 2 (footprint, physical mapping) prefilters S in light space up to a pixel's
// footprint; the screen-space passes then add only the variance S does not yet carry.
//
// A point light's six faces (shadow_common.glsl): S from the texels of the receiver's own face
// (its guard band holds the 2 x 2 footprint), the footprint prefilter's taps placed by direction
// (shadow_tap), every distance taken along the ray from the light.
//
// Written per pixel (layout in mpg_common.glsl): background (0, 0, 0, 0); lit or outside the
// shadow map (0, 0, z, 0); receiver facing away from the light (1, 0, z, 0): its own umbra,
// never filtered (the reference counts such receivers as fully shadowed); shadowed (S, D, z, 0).
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "mpg_common.glsl"
#include "kernel_shape.glsl"
#include "common/receiver_plane.glsl"

layout(rgba16f, binding = 0) uniform writeonly image2D u_distance_map;
layout(rgba16f, binding = 1) uniform writeonly image2D u_kernel_shape;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_shadow_map;    // light window depth, nearest, clamp to edge
uniform float u_depth_bias;        // window depth
uniform float u_distance_power;    // Dp
uniform float u_distance_multiplier;  // Dm
uniform float u_light_size_scale;  // multiplies the light's diameter (physical)
uniform float u_focal_px;          // screen height / (2 tan(fov_y / 2)): pixels per world unit at depth 1
uniform mat4 u_view_proj;          // camera, world -> clip
uniform int u_anisotropic;         // 1: shaped kernels (kernel_shape.glsl), 0: round
uniform float u_max_kernel;        // pixels
uniform int u_max_passes;
uniform float u_pass_variance[65]; // [n]: per-axis variance (pixels^2) after n full blur passes
uniform float u_footprint_spread;  // SHADOW_TEST 2: largest spread of the light-space prefilter, pixels
#if D_TILES
layout(r8, binding = 2) uniform writeonly image2D u_d_tiles;  // 1 where the 16 x 16 tile has D > 0
#include "tile_marks.glsl"
#endif

// World units across the light per shadow-map UV unit, at a receiver d_r from the light.
float world_per_uv(float d_r) {
  return u_light_ortho == 1 ? light_frustum_width() : max(d_r, 1e-4) * light_frustum_width();
}

// World-unit penumbra width across the light direction (Fernando 2005, eq. 1, scene/light.h).
float penumbra_width_world(float d_r, float d_b) { return penumbra_width_uv(d_r, d_b) * world_per_uv(d_r); }

// Fractional number of multi-pass blurs whose summed variance is `variance` (pixels^2); a
// fraction f of a pass blends the pass's result by f (multipass_blur.comp.glsl), adding f times
// its variance, so the inverse is piecewise linear.
float passes_for_variance(float variance) {
  for (int n = 0; n < u_max_passes; ++n) {
    float lo = u_pass_variance[n], hi = u_pass_variance[n + 1];
    if (variance <= hi) return float(n) + (variance - lo) / max(hi - lo, 1e-6);
  }
  return float(u_max_passes);
}

// S and the blocker's window depth at shadow coordinate c (uv, window depth).
// SHADOW_TEST 0 nearest: the paper's bit, one comparison with the nearest texel; the blocker is
//   that texel. 1 bilinear: the four texels around c compared and weighted bilinearly (what a
//   hardware comparison sampler returns), so S carries the edge's position inside the texel and
//   the screen-space filters start from an edge that is not quantised to texels; the blocker is
//   the mean depth of the texels that shadow.
float hard_shadow(vec3 c, out float blocker) {
  ivec2 size = textureSize(u_shadow_map, 0);
  float receiver = c.z - u_depth_bias;
#if SHADOW_TEST == 0
  blocker = texelFetch(u_shadow_map, clamp(ivec2(c.xy * vec2(size)), ivec2(0), size - 1), 0).r;
  return receiver > blocker ? 1.0 : 0.0;
#else
  vec2 t = c.xy * vec2(size) - 0.5;  // texel-centre coordinates
  vec2 f = fract(t);
  vec4 depths = textureGather(u_shadow_map, (floor(t) + 1.0) / vec2(size), 0);  // (0,1) (1,1) (1,0) (0,0)
  vec4 weights = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  vec4 blocks = vec4(greaterThan(vec4(receiver), depths));
  blocker = dot(blocks, depths) / max(dot(blocks, vec4(1.0)), 1.0);
  // Exactly 1 when all four shadow (the weights need not sum to 1 in floating point): the umbra
  // early-out tests S >= 1.
  return all(greaterThan(blocks, vec4(0.5))) ? 1.0 : dot(weights, blocks);
#endif
}

// SHADOW_TEST 2: S prefiltered in the shadow map by a Gaussian of spread sigma_uv: 5 x 5 bilinear
// comparisons h sigma apart with weights exp(-k^2 / 2), k = -2..2, whose per-axis variance is
// 0.9235 h^2 sigma^2, so h = 1.0406; each compared against the receiver plane (Isidoro 2006,
// receiver_plane.glsl; shadow_tap places each tap, by direction for six faces). `blockers` counts
// the taps that found a blocker, `blocker` is the distance from the light of their mean window
// depth (six faces: their mean distance along the taps' rays; a face's depths are its own).
float prefiltered_shadow(Receiver r, float sigma_uv, out float blocker, out float blockers) {
  const float weight[5] = float[](0.1353, 0.6065, 1.0, 0.6065, 0.1353);
  const float h = 1.0406;
  float s = 0.0, sum = 0.0;
  blocker = 0.0;
  blockers = 0.0;
  bool all_shadowed = true;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      float b;
      ShadowTap tap = shadow_tap(r, h * sigma_uv * vec2(i - 2, j - 2), 0.0);
      float t = hard_shadow(vec3(tap.uv, tap.ref), b);
      float w = weight[i] * weight[j];
      s += w * t;
      sum += w;
      all_shadowed = all_shadowed && t >= 1.0;
      if (t > 0.0) {
        blocker += kLightFaces == 1 ? b : light_distance(b) * tap.distance_scale;
        blockers += 1.0;
      }
    }
  blocker /= max(blockers, 1.0);
  if (kLightFaces == 1) blocker = light_distance(blocker);
  return all_shadowed ? 1.0 : s / sum;
}

// D for an edge whose occluder distance is d_r - d_b; `prefiltered_px` is the spread (pixels)
// that S already carries (SHADOW_TEST 2): variances add, so the screen-space filters supply the
// rest, spread^2 - prefiltered^2.
float filter_control(float d_r, float d_b, float pixels_per_world, float prefiltered_px) {
  float occluder = max(d_r - d_b, 0.0);  // world units
#if MAPPING == 0
  float depth_range = max(u_light_far - u_light_near, 1e-6);
  return pow(occluder / depth_range, u_distance_power) * u_distance_multiplier;
#else
  // Standard deviation of the edge ramp, pixels.
  float spread = 0.25 * penumbra_width_world(d_r, d_b) * u_light_size_scale * pixels_per_world;
  spread = sqrt(max(spread * spread - prefiltered_px * prefiltered_px, 0.0));
#if ALTERATION == 0
  return min(sqrt(12.0) * spread, u_max_kernel);
#elif ALTERATION == 1
  return min(spread / 0.2477, u_max_kernel);
#else
  return passes_for_variance(spread * spread);
#endif
#endif
}

// Writes pixel p of both maps; returns its D.
float write_distance(ivec2 p) {
  vec4 pos = gbuffer_position(u_depth, p);
  vec4 value = vec4(0.0, 0.0, max(pos.w, 0.0), 0.0);
  KernelShape shape;
  shape.a = vec3(1.0, 0.0, 1.0);
  shape.depth_gradient = vec2(0.0);
  if (pos.w > 0.0) {
    vec3 n = normalize(gbuffer_normal(u_normal, p));
    shape = receiver_kernel_shape(u_view_proj, vec2(imageSize(u_distance_map)), pos.xyz, n, pos.w,
                                  u_anisotropic == 1, u_focal_px);
    vec3 c = shadow_coord(pos.xyz);
    bool in_map = all(greaterThanEqual(c, vec3(0.0))) && all(lessThanEqual(c, vec3(1.0)));
    if (faces_away_from_light(pos.xyz, n)) {
      value.r = 1.0;
    } else if (in_map) {
      float blocker;
#if SHADOW_TEST == 2 && MAPPING == 1
      // Footprint prefilter (not in the paper): a screen-space filter of a per-pixel hard test
      // cannot make a penumbra narrower than the pixel spacing, nor see a feature between two
      // pixel centres, so S is the shadow map filtered in light space by a Gaussian of the
      // penumbra's own spread, at most u_footprint_spread pixels; the blockers found by the
      // widest one set that spread, and D asks the screen-space passes for the rest.
      Receiver r;
      r.coord = c;
      r.world = pos.xyz;
      r.normal = n;
      r.dz_duv = vec2(0.0);
      add_receiver_plane(u_depth, p, r);
      float d_r = receiver_light_distance(r), blockers;
      float px_per_uv = shape.pixels_per_world * world_per_uv(d_r);
      float cap_uv = u_footprint_spread / px_per_uv;
      value.r = prefiltered_shadow(r, cap_uv, blocker, blockers);
      if (blockers > 0.0) {
        float spread_uv = 0.25 * penumbra_width_uv(d_r, blocker) * u_light_size_scale;
        float pre_uv = min(spread_uv, cap_uv);
        // Shadowed across the widest footprint: the narrower one lies inside it.
        if (pre_uv < cap_uv && value.r < 1.0) value.r = prefiltered_shadow(r, pre_uv, blocker, blockers);
        if (blockers > 0.0)
          value.g = filter_control(d_r, blocker, shape.pixels_per_world, pre_uv * px_per_uv);
      }
#else
      value.r = hard_shadow(c, blocker);
      float to_ray = axis_to_ray_scale(pos.xyz);  // six faces: distances along the receiver's ray
      if (value.r > 0.0)
        value.g = filter_control(light_distance(c.z) * to_ray, light_distance(blocker) * to_ray,
                                 shape.pixels_per_world, 0.0);
#endif
    }
  }
  imageStore(u_distance_map, p, value);
  imageStore(u_kernel_shape, p, vec4(shape.a.xy, shape.depth_gradient));
  return value.g;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  bool inside = all(lessThan(p, imageSize(u_distance_map)));
#if D_TILES
  tile_marks_begin();
  if (inside) tile_marks_note(write_distance(p) > 0.0);
  bool marked = tile_marks_end();
  if (gl_LocalInvocationIndex == 0u) imageStore(u_d_tiles, ivec2(gl_WorkGroupID.xy), vec4(marked ? 1.0 : 0.0));
#else
  if (inside) write_distance(p);
#endif
}
