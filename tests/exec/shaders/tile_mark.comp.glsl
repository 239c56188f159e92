#version 450 core
// Test writer of a tile list: one 8 x 8 work group per tile of the image; a tile is listed when
// any of its pixels lies inside the disk (u_centre, u_radius), pixel centres at + 0.5.
layout(local_size_x = 8, local_size_y = 8) in;
#include "tile_list.glsl"
uniform ivec2 u_size;
uniform vec2 u_centre;
uniform float u_radius;
shared uint s_inside;
void main() {
  if (gl_LocalInvocationIndex == 0u) s_inside = 0u;
  barrier();
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(p, u_size)) && distance(vec2(p) + 0.5, u_centre) <= u_radius) atomicOr(s_inside, 1u);
  barrier();
  if (gl_LocalInvocationIndex == 0u && s_inside != 0u) tile_list_append(gl_WorkGroupID.xy);
}
