#version 450 core
// Test reader of a tile list: one 8 x 8 work group per listed tile writes 1 at its pixels.
layout(local_size_x = 8, local_size_y = 8) in;
#include "tile_list.glsl"
layout(r32f, binding = 0) uniform writeonly image2D u_out;
void main() {
  ivec2 p = tile_list_pixel();
  if (any(greaterThanEqual(p, imageSize(u_out)))) return;
  imageStore(u_out, p, vec4(1.0));
}
