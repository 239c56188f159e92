// Reading the frame contract (technique/frame_graph.h): every pass that needs a receiver's
// position or normal includes this file and binds `gbuffer_depth` (R32F linear view depth,
// 0 = background) and `gbuffer_normal` (RG16, octahedral). 8 bytes per pixel instead of the
// 24 that a stored RGBA32F position and RGBA16F normal cost.
#include "frame_uniforms.glsl"

// Octahedral normal encoding (Cigolle et al. 2014, "A Survey of Efficient Representations for
// Independent Unit Vectors", section 3.1): the unit sphere folded onto the [-1, 1]^2 square,
// stored as UNORM in [0, 1]^2.
vec2 octahedral_wrap(vec2 v) { return (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

vec2 encode_normal(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 e = n.z >= 0.0 ? n.xy : octahedral_wrap(n.xy);
  return e * 0.5 + 0.5;
}

vec3 decode_normal(vec2 stored) {
  vec2 e = stored * 2.0 - 1.0;
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = octahedral_wrap(n.xy);
  return normalize(n);
}

// World position of G-buffer pixel `pixel` whose linear view depth is `view_depth`: the
// pixel centre's camera ray (linear in the pixel, set up once per frame: exec::PixelRays),
// scaled to that depth.
vec3 world_from_view_depth(ivec2 pixel, float view_depth) {
  vec2 xy = vec2(pixel) + 0.5;
  vec3 ray = frame_ray00.xyz + xy.x * frame_ray_dx.xyz + xy.y * frame_ray_dy.xyz;
  return frame_camera_position.xyz + view_depth * ray;
}

// What a stored position texel used to hold: world xyz, w = linear view depth (> 0), or
// w = 0 for background.
vec4 gbuffer_position(sampler2D depths, ivec2 pixel) {
  float d = texelFetch(depths, pixel, 0).r;
  return d > 0.0 ? vec4(world_from_view_depth(pixel, d), d) : vec4(0.0);
}

vec3 gbuffer_normal(sampler2D normals, ivec2 pixel) { return decode_normal(texelFetch(normals, pixel, 0).rg); }
