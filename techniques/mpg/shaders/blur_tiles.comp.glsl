#version 450 core
// Where the multi-pass blur (multipass_blur.comp.glsl) has work: one work group per screen tile
// reads D of its pixels from the distance map the blur starts from. A pixel changes on pass k
// exactly while its D - k > 0 (D counts down by one a pass), so a tile changes on passes
// 0 .. m - 1 with m = ceil(max D over the tile). Tiles with m > 0 are appended to the list; m
// goes to the per-tile texture, so that pass k can skip a listed tile once it is still for good.
#include "screen_pass.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_tile_passes;
uniform sampler2D u_distance_map;

shared uint s_max_d;  // float bits: D >= 0 orders like its bit pattern

void main() {
  if (gl_LocalInvocationIndex == 0u) s_max_d = 0u;
  barrier();
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(p, textureSize(u_distance_map, 0)))) {
    float d = texelFetch(u_distance_map, p, 0).g;
    if (d > 0.0) atomicMax(s_max_d, floatBitsToUint(d));
  }
  barrier();
  if (gl_LocalInvocationIndex != 0u) return;
  float passes = ceil(uintBitsToFloat(s_max_d));
  imageStore(u_tile_passes, ivec2(gl_WorkGroupID.xy), vec4(min(passes, 2048.0)));
  if (passes > 0.0) tile_list_append(gl_WorkGroupID.xy);
}
