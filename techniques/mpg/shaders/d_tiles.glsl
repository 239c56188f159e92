// Which 16 x 16 screen tiles hold a pixel with D > 0 (R8 per tile: 1 or 0), so the dilation can
// skip its taps where no D > 0 lies within their reach (the result is then 0 without them).
// The writer (pass 2) and the readers (pass 3) run one work group per tile: screen_pass.glsl's
// 16 x 16 groups, aligned with the tiles. Every invocation of the group must call these (they
// hold barriers), so callers test "inside the image" after, not before.
// The includer declares u_d_tiles: the writer (D_TILES_WRITE) an r8 writeonly image2D, a reader
// a sampler2D.
shared uint s_d_tiles_any;

#ifdef D_TILES_WRITE
// d_tiles_begin(); then d_tiles_note(D) per pixel; then d_tiles_store().
void d_tiles_begin() {
  if (gl_LocalInvocationIndex == 0u) s_d_tiles_any = 0u;
  barrier();
}
void d_tiles_note(float d) {
  if (d > 0.0) atomicOr(s_d_tiles_any, 1u);
}
void d_tiles_store() {
  barrier();
  if (gl_LocalInvocationIndex == 0u) imageStore(u_d_tiles, ivec2(gl_WorkGroupID.xy), vec4(float(s_d_tiles_any)));
}
#else
// Whether a tile within `reach` tiles of this group's (a square) has D > 0.
bool d_tiles_near(int reach) {
  if (gl_LocalInvocationIndex == 0u) s_d_tiles_any = 0u;
  barrier();
  int side = 2 * reach + 1;
  ivec2 grid = textureSize(u_d_tiles, 0);
  uint threads = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
  for (int i = int(gl_LocalInvocationIndex); i < side * side; i += int(threads)) {
    ivec2 t = ivec2(gl_WorkGroupID.xy) + ivec2(i % side, i / side) - reach;
    if (all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, grid)) && texelFetch(u_d_tiles, t, 0).r > 0.0)
      atomicOr(s_d_tiles_any, 1u);
  }
  barrier();
  return s_d_tiles_any != 0u;
}
#endif
