#version 450 core
// msm_mask: one thread per screen pixel. The filtered moments at the receiver's shadow-map
// position (bilinear), back to canonical moments b = (E z, E z^2, E z^3, E z^4), biased towards
// (0.5, 0.5, 0.5, 0.5) by the moment bias alpha, then the Hamburger 4MSM reconstruction (Peters &
// Klein 2015, Algorithm 2): the Cholesky factorisation of the Hankel matrix, the two other support
// points z1, z2 of the three-point distribution through the receiver depth z0, and the shadow
// intensity as the weight of the support points in front of z0. CONTACT_HARDENING (this example's
// addition, README.md): the same from the wider-filtered moments, whose support points in front of
// z0 give the blockers' mean depth; their height above the receiver mixes the two shadows.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "common/receiver_plane.glsl"  // receiver_at(): lit, facing away (0) or to filter

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;       // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;      // gbuffer_normal
uniform sampler2D u_moments;     // optimised moments (msm_moments.frag.glsl), filtered narrow
uniform sampler2D u_moments_wide;  // the same, filtered wide (CONTACT_HARDENING only)
uniform float u_narrow_height;   // the penumbra heights the two filters match, fractions of the
                                 // scene's height along the light (u_blocker_height_scale)
uniform float u_wide_height;
uniform mat4 u_to_canonical;     // the inverse of msm_moments' transform
uniform vec4 u_optimised_offset;
uniform float u_moment_bias;     // alpha
uniform float u_depth_bias;      // window depth

// The shadow intensity, and in blocker_depth the mean depth of the support points in front of
// z0 (their weights from the moments b = w0 (1, z0, z0^2) + w1 (1, z1, z1^2) + w2 (...)).
float shadow_intensity(vec4 optimised, float z0, out float blocker_depth) {
  vec4 b = mix(u_to_canonical * (optimised - u_optimised_offset), vec4(0.5), u_moment_bias);
  float l32_d22 = -b.x * b.y + b.z;
  float d22 = -b.x * b.x + b.y;
  float squared_depth_variance = -b.y * b.y + b.w;
  float d33_d22 = dot(vec2(squared_depth_variance, -l32_d22), vec2(d22, l32_d22));
  float inv_d22 = 1.0 / d22;
  float l32 = l32_d22 * inv_d22;
  vec3 c = vec3(1.0, z0, z0 * z0);
  c.y -= b.x;  // L c1 = (1, z0, z0^2)
  c.z -= b.y + l32 * c.y;
  c.y *= inv_d22;  // D c2 = c1
  c.z *= d22 / d33_d22;
  c.y -= l32 * c.z;  // L^T c3 = c2
  c.x -= dot(c.yz, b.xy);
  // Roots of c.x + c.y z + c.z z^2: the other support points.
  float p = c.y / c.z, q = c.x / c.z;
  float r = sqrt(max(p * p * 0.25 - q, 0.0));
  float z1 = -p * 0.5 - r, z2 = -p * 0.5 + r;
  blocker_depth = z0;
  if (z2 < z0) {  // z1, z2 in front: the shadow is 1 - w0
    float w0 = (z1 * z2 - b.x * (z1 + z2) + b.y) / ((z0 - z1) * (z0 - z2));
    blocker_depth = (b.x - w0 * z0) / max(1.0 - w0, 1e-6);
    return clamp(1.0 - w0, 0.0, 1.0);
  }
  if (z1 < z0) {  // z1 alone in front: the shadow is w1
    blocker_depth = z1;
    return clamp((z0 * z2 - b.x * (z0 + z2) + b.y) / ((z2 - z1) * (z0 - z1)), 0.0, 1.0);
  }
  return 0.0;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  Receiver r;
  const int kind = receiver_at(u_depth, u_normal, p, r);
  float lit = kind == RECEIVER_LIT ? 1.0 : 0.0;  // facing away from the light: its own shadow
  if (kind == RECEIVER_FILTERED) {
    float z0 = r.coord.z - u_depth_bias, blocker;
    float shadow = shadow_intensity(textureLod(u_moments, r.coord.xy, 0.0), z0, blocker);
#if CONTACT_HARDENING
    // The wide map finds the blockers; their height above the receiver picks the filter width
    // between the two maps' (linear in height, like a penumbra's width).
    float wide = shadow_intensity(textureLod(u_moments_wide, r.coord.xy, 0.0), z0, blocker);
    float height = (light_distance(z0) - light_distance(blocker)) / u_blocker_height_scale;
    shadow = mix(shadow, wide, clamp((height - u_narrow_height) / max(u_wide_height - u_narrow_height, 1e-4), 0.0, 1.0));
#endif
    lit = 1.0 - shadow;
  }
  imageStore(u_mask, p, vec4(lit));
}
