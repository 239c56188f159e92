// A tile list (graph/resources.h): the screen tiles one pass found work in, for a later pass to
// dispatch over with one work group per tile (PassContext::dispatch_over_tiles). The header is
// the indirect dispatch arguments, so the GPU reads the count itself: tiles appended (work
// groups in x), 1, 1, and a reserved word; then one entry per tile, x | y << 16.
// Define TILE_LIST_BINDING (the storage-buffer binding the pass binds it at) before including.
#ifndef TILE_LIST_BINDING
#define TILE_LIST_BINDING 0
#endif
layout(std430, binding = TILE_LIST_BINDING) buffer TileList {
  uint tile_list_count;  // = work groups in x of the indirect dispatch
  uint tile_list_groups_y;
  uint tile_list_groups_z;
  uint tile_list_reserved;
  uint tile_list_entries[];
};

// Writer: one call per tile that needs work (at most once per tile: the list holds every tile
// of the grid, no more).
void tile_list_append(uvec2 tile) {
  uint i = atomicAdd(tile_list_count, 1u);
  tile_list_entries[i] = tile.x | (tile.y << 16);
}

// Reader: the tile this work group runs over, and the pixel of this invocation in it (the
// work group's local size is the tile).
uvec2 tile_list_tile() {
  uint e = tile_list_entries[gl_WorkGroupID.x];
  return uvec2(e & 0xffffu, e >> 16);
}
ivec2 tile_list_pixel() { return ivec2(tile_list_tile() * gl_WorkGroupSize.xy + gl_LocalInvocationID.xy); }
