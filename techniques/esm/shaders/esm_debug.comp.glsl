#version 450 core
// Debug views of the extended shadow map for the viewer: the edge-distance channel decoded to a
// signed distance from the silhouette edge in texels (> 0 outside the occluder, between -1.41
// and 2.83; 0 where no quad wrote), and the silhouette mask (1 where one did).
#include "screen_pass.glsl"
#include "esm_common.glsl"
layout(r32f, binding = 0) uniform writeonly image2D u_edge_distance;
layout(r16f, binding = 1) uniform writeonly image2D u_silhouette_mask;
uniform sampler2D u_edge;  // the edge channel (esm_common.glsl)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_edge_distance)))) return;
  vec4 t = esm_decode(vec2(texelFetch(u_edge, p, 0).r, 0.0));
  float mask = t.a > 0.5 ? 1.0 : 0.0;
  imageStore(u_edge_distance, p, vec4(t.g));
  imageStore(u_silhouette_mask, p, vec4(mask));
}
