// The multi-pass blur's tile list (multipass_blur.comp.glsl): a pixel changes on blur pass k
// exactly while its D - k > 0 (D counts down by one a pass), so a tile changes on passes
// 0 .. m - 1 with m = ceil(max D over the tile). Tiles with m > 0 are appended to the list
// (tile_list.glsl, at screen_pass.glsl's binding) and m goes to the per-tile u_tile_passes (an r16f
// image the includer declares), so pass k can skip a listed tile once it is still for good.
// Written by the last pass that sets D, one work group per 16 x 16 tile (blur_tiles.comp.glsl,
// or the dilation's y pass); every invocation must call these (they hold barriers).
shared uint s_blur_max_d;  // float bits: D >= 0 orders like its bit pattern

void blur_list_begin() {
  if (gl_LocalInvocationIndex == 0u) s_blur_max_d = 0u;
  barrier();
}
void blur_list_note(float d) {
  if (d > 0.0) atomicMax(s_blur_max_d, floatBitsToUint(d));
}
void blur_list_end() {
  barrier();
  if (gl_LocalInvocationIndex != 0u) return;
  float passes = ceil(uintBitsToFloat(s_blur_max_d));
  imageStore(u_tile_passes, ivec2(gl_WorkGroupID.xy), vec4(min(passes, 2048.0)));
  if (passes > 0.0) tile_list_append(gl_WorkGroupID.xy);
}
