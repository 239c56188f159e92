#version 450 core
// The extended shadow map cleared to a texel's "no edge" values (esm_depth_pass.cpp) by a compute
// dispatch: on the GPUs we measure, glClearTexImage of a float texture goes through the few
// raster units (1.2 ms for 2048^2 on an H100, against the depth pass's 0.5 ms), a compute store
// runs at memory speed.
layout(local_size_x = 16, local_size_y = 16) in;
layout(r32f, binding = 0) uniform writeonly image2D u_edge;
layout(r32f, binding = 1) uniform writeonly image2D u_edge_depth;
layout(r32f, binding = 2) uniform writeonly image2D u_edge_near;  // 0: no edge, in either mode
uniform vec2 u_value;  // (edge, edge_depth)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_edge)))) return;
  imageStore(u_edge, p, vec4(u_value.x));
  imageStore(u_edge_depth, p, vec4(u_value.y));
  imageStore(u_edge_near, p, vec4(0.0));
}
