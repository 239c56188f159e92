#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Lambert + ambient with base colour, shadowed by the technique's shadow_mask, then tone
// mapped (Reinhard on luminance-free RGB) and encoded with gamma 2.2 into RGBA8.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
layout(rgba8, binding = 0) uniform writeonly image2D u_color;
uniform sampler2D u_albedo;
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_shadow_mask;
// u_light_dir (unit, light -> scene) and u_light_pos: shadow_common.glsl's.
uniform vec3 u_light_color;   // linear, times intensity
uniform int u_light_spot;
uniform int u_light_point;    // 1: light in every direction from u_light_pos, no cone
uniform float u_spot_cos;     // cos(cone half-angle)
uniform float u_ambient;
uniform int u_cascade_tint;   // 1: tint each pixel by the cascade it reads (scene/cascades.h)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_color);
  if (any(greaterThanEqual(p, size))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  if (pos.w <= 0.0) {
    // Background: a quiet vertical gradient so silhouettes read against it.
    float t = float(p.y) / float(size.y);
    imageStore(u_color, p, vec4(mix(vec3(0.55, 0.6, 0.68), vec3(0.25, 0.33, 0.45), t), 1.0));
    return;
  }
  vec3 albedo = texelFetch(u_albedo, p, 0).rgb;
  vec3 n = normalize(gbuffer_normal(u_normal, p));
  float visibility = clamp(texelFetch(u_shadow_mask, p, 0).r, 0.0, 1.0);
  vec3 l = -u_light_dir;
  float cone = 1.0;
  if (u_light_spot == 1) {
    l = normalize(u_light_pos - pos.xyz);
    cone = smoothstep(u_spot_cos, mix(u_spot_cos, 1.0, 0.2), dot(-l, u_light_dir));
  } else if (u_light_point == 1) {
    l = normalize(u_light_pos - pos.xyz);
  }
  float ndotl = max(dot(n, l), 0.0);
  vec3 radiance = albedo * (u_ambient + u_light_color * ndotl * visibility * cone);
  if (kCascades > 1 && u_cascade_tint == 1) {  // red, green, blue, yellow from the nearest
    const vec3 tints[4] = vec3[](vec3(1.0, 0.45, 0.45), vec3(0.45, 1.0, 0.45), vec3(0.5, 0.6, 1.0), vec3(1.0, 0.95, 0.4));
    shadow_coord(pos.xyz);  // sets g_cascade; kCascades where no cascade holds the pixel
    if (g_cascade < kCascades) radiance *= tints[g_cascade];
  }
  vec3 mapped = radiance / (1.0 + radiance);
  imageStore(u_color, p, vec4(pow(mapped, vec3(1.0 / 2.2)), 1.0));
}
