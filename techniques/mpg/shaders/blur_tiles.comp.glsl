#version 450 core
// Where the multi-pass blur (multipass_blur.comp.glsl) has work, when no dilation runs before it
// (the dilation's y pass writes the list itself): one work group per screen tile reads D of its
// pixels from the distance map the blur starts from (blur_tile_list.glsl).
#include "screen_pass.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_tile_passes;
uniform sampler2D u_distance_map;
#include "blur_tile_list.glsl"

void main() {
  blur_list_begin();
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(p, textureSize(u_distance_map, 0)))) blur_list_note(texelFetch(u_distance_map, p, 0).g);
  blur_list_end();
}
