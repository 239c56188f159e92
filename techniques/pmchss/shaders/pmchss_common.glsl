// Shared pieces of the pmchss passes (Sterna 2018, "Contact-hardening Soft Shadows Made Fast").
// Needs: common/shadow_common.glsl, sampling/sampling.glsl, common/receiver_plane.glsl included
// first.
//
// Depth domains: the shadow map holds the light's WINDOW depth in [0, 1]; comparisons happen
// there (with bias). The penumbra mapping works on light-VIEW distances in world units
// (light_distance()), as the paper's demo does ("depths are all in shadow map's view space",
// section 2.1). A point light's six faces: every tap placed by direction (shadow_tap,
// receiver_plane.glsl), distances along the taps' rays.

// Set by set_pmchss_uniforms() (pmchss_uniforms.cpp).
uniform float u_shadow_filter_max_size;  // shadow-map UV, radius of the largest PCF kernel
uniform float u_search_radius;           // shadow-map UV: kernel scale x shadow_filter_max_size
uniform float u_penumbra_k;              // Listing 4's 80
uniform float u_depth_bias;              // window depth units
uniform int u_receiver_plane;            // 1: tilt comparisons along the receiver plane

// Rotation phi of the Vogel disk of receiver `r` at `pixel` (tap_rotation, receiver_plane.glsl:
// on the surface by default). The paper's (rotation_noise=screen) is 2 pi IGN of the pixel
// (section 1.2); checkerboard mode multiplies its y by 4 (section 3, Listing 7): with only every
// other pixel computed, the unmodified noise "looked less random".
float pmchss_noise_phi(Receiver r, ivec2 pixel, bool checker) {
  vec2 centre = vec2(pixel) + 0.5;
  if (checker) centre.y *= 4.0;
  return tap_rotation(r, centre);
}

// The tap at uv offset `o` and the receiver depth it is compared with: the receiver plane's depth
// there minus the constant bias (shadow_tap, passes/common/receiver_plane.glsl: the code every
// filtering technique shares); with receiver_plane_bias off, the plane is flat (one view; six
// faces always meet the receiver's plane along the tap's ray).
ShadowTap pmchss_tap(Receiver r, vec2 o) {
  if (u_receiver_plane == 0) r.dz_duv = vec2(0.0);
  return shadow_tap(r, o, u_depth_bias);
}

// A receiver of the G-buffer at `pixel` (world position `pos`) in light space: coordinate, world
// position, normal and receiver plane.
Receiver pmchss_receiver(sampler2D depths, sampler2D normals, ivec2 pixel, vec3 pos) {
  Receiver r;
  r.world = pos;
  r.normal = gbuffer_normal(normals, pixel);
  r.coord = shadow_coord(pos);
  r.dz_duv = vec2(0.0);
  add_receiver_plane(depths, pixel, r);
  return r;
}

// Average blocker search, section 2.1, Listing 3: N Vogel taps inside the search radius, point
// sampled; taps closer to the light than the receiver are blockers and their depths averaged.
// Returns the number of blockers; `avg_distance` is the distance from the light (world units)
// of their mean depth, the far plane where there is none.
// Search radius, shadow-map UV. The paper's is fixed: penumbra_kernel_scale x the largest
// kernel radius (section 2.2: wider than the filter, so the low-resolution mask covers the whole
// penumbra). The physical mapping knows this receiver's largest kernel: half the penumbra of a
// blocker at the map's near plane (blocker_search_width_uv in shadow_common.glsl, as PCSS
// searches), so it scales that instead; on thin, close casters the fixed region averages in far
// blockers of other receivers (poles: penumbra RMSE 0.108 -> 0.079, techniques/pmchss/README.md).
// The penumbra mask (PENUMBRA_MASK_SEARCH) keeps the paper's fixed region in every mapping: it is
// blurred afterwards, so it must find blockers beyond the penumbra it marks.
float pmchss_search_radius(Receiver r) {
#if PENUMBRA_MAPPING == 1 && !defined(PENUMBRA_MASK_SEARCH)
  float largest_kernel = min(0.5 * blocker_search_width_uv(receiver_light_distance(r)), u_shadow_filter_max_size);
  return largest_kernel * (u_search_radius / u_shadow_filter_max_size);
#else
  return u_search_radius;
#endif
}

float pmchss_blocker_search(sampler2D shadow_map, Receiver r, int n, float phi, out float avg_distance) {
  float sum = 0.0;
  float count = 0.0;
  const float radius = pmchss_search_radius(r);
  for (int i = 0; i < n; ++i) {
    ShadowTap t = pmchss_tap(r, radius * vogel_disk_sample(i, n, phi));
    float d = textureLod(shadow_map, t.uv, 0.0).r;
    // One view averages window depths as Listing 3 does (k was calibrated so); six faces' window
    // depths belong to different faces, so their distances along the rays are averaged.
    if (d < t.ref) {
      sum += kLightFaces == 1 ? d : light_distance(d) * t.distance_scale;
      count += 1.0;
    }
  }
  if (count > 0.0 && kLightFaces == 1) sum = light_distance(sum / count) * count;
  avg_distance = count > 0.0 ? sum / count : u_light_far;
  return count;
}

// Penumbra in [0, 1] = fraction of shadow_filter_max_size used as the PCF kernel radius.
// PENUMBRA_MAPPING (a define, from the penumbra_mapping parameter):
//   0 paper:    p = (z - z_avg) / z_avg, saturate(k p^2)                (section 2.1, Listing 4)
//   1 physical: PCSS width (Fernando 2005, the paper's Listing 5) for the light model of
//               scene/light.h, in shadow-map UV at the receiver (penumbra_width_uv in
//               shadow_common.glsl); the kernel radius is w / 2 (a disk kernel of radius R
//               turns a hard edge into a ramp 2R wide).
//   2 fixed:    1, no contact hardening (Table 1's "Regular Shadow Mask")
// d_r, d_b: the receiver's and the mean blocker's distances from the light, world units.
float pmchss_penumbra_from_blocker(float d_r, float d_b) {
#if PENUMBRA_MAPPING == 2
  return 1.0;
#else
  d_b = max(d_b, 1e-4);
#if PENUMBRA_MAPPING == 0
  float p = (d_r - d_b) / d_b;
  return clamp(u_penumbra_k * p * p, 0.0, 1.0);
#else
  float radius_uv = 0.5 * penumbra_width_uv(d_r, d_b);
  return clamp(radius_uv / u_shadow_filter_max_size, 0.0, 1.0);
#endif
#endif
}

// Soft shadow of Listing 6: FILTER_SAMPLES Vogel taps over penumbra x shadow_filter_max_size,
// each a hardware 2x2 bilinear comparison (sampler2DShadow, "SampleCmp" in the paper).
float pmchss_filter(sampler2DShadow shadow_cmp, Receiver r, float penumbra, float phi) {
  float lit = 0.0;
  float radius = penumbra * u_shadow_filter_max_size;
  // A kernel narrower than a texel puts all FILTER_SAMPLES taps on the same 2x2 footprint:
  // one tap gives the same value (this is where the paper's penumbra-mask speed-up comes from
  // on a GPU whose cache already holds the whole shadow map: contact and fully lit pixels).
  if (radius < 0.5 * u_shadow_texel) {
    ShadowTap t = pmchss_tap(r, vec2(0.0));
    return texture(shadow_cmp, vec3(t.uv, t.ref));
  }
  for (int i = 0; i < FILTER_SAMPLES; ++i) {
    ShadowTap t = pmchss_tap(r, radius * vogel_disk_sample(i, FILTER_SAMPLES, phi));
    lit += texture(shadow_cmp, vec3(t.uv, t.ref));
  }
  return lit / float(FILTER_SAMPLES);
}

// Shadow-map coordinate of a world position, or false outside the light frustum (lit).
bool pmchss_in_shadow_frustum(vec3 c) {
  return all(greaterThanEqual(c, vec3(0.0))) && all(lessThanEqual(c, vec3(1.0)));
}
