// Marks per 16 x 16 screen tile (R8: 1 or 0), so a later pass can skip taps where no marked value
// lies within their reach: pass 2 marks the tiles with D > 0 (d_tiles), the dilation's x pass the
// tiles with a non-zero row maximum (a_tiles, what its y pass reads). Writers and readers run one
// work group per tile (screen_pass.glsl's 16 x 16 groups, aligned with the tiles). Every
// invocation of the group must call these (they hold barriers): callers test "inside the image"
// after, not before.
shared uint s_tile_marks_note;
shared uint s_tile_marks_near;

// Writer: tile_marks_begin(); tile_marks_note() per pixel; then tile_marks_end() is the tile's
// mark (invocation 0 stores it).
void tile_marks_begin() {
  if (gl_LocalInvocationIndex == 0u) s_tile_marks_note = 0u;
  barrier();
}
void tile_marks_note(bool marked) {
  if (marked) atomicOr(s_tile_marks_note, 1u);
}
bool tile_marks_end() {
  barrier();
  return s_tile_marks_note != 0u;
}

// Reader: whether a tile within `reach` tiles of this group's (a square) is marked.
bool tile_marks_near(sampler2D marks, int reach) {
  if (gl_LocalInvocationIndex == 0u) s_tile_marks_near = 0u;
  barrier();
  int side = 2 * reach + 1;
  ivec2 grid = textureSize(marks, 0);
  int threads = int(gl_WorkGroupSize.x * gl_WorkGroupSize.y);
  for (int i = int(gl_LocalInvocationIndex); i < side * side; i += threads) {
    ivec2 t = ivec2(gl_WorkGroupID.xy) + ivec2(i % side, i / side) - reach;
    if (all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, grid)) && texelFetch(marks, t, 0).r > 0.0)
      atomicOr(s_tile_marks_near, 1u);
  }
  barrier();
  return s_tile_marks_near != 0u;
}
