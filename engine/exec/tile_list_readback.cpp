#include "exec/tile_list_readback.h"

#include <algorithm>

namespace penumbra::exec {

std::optional<TileListCount> dispatched_tiles(const Executor& executor, const graph::PlannedPass& pass) {
  const graph::PlannedBinding* list = graph::dispatch_tile_list(pass);
  if (!list) return std::nullopt;
  const auto& passes = executor.plan().passes;
  if (&pass < passes.data() || &pass >= passes.data() + passes.size() ||
      !executor.dispatched_over_tiles(static_cast<size_t>(&pass - passes.data())))
    return std::nullopt;
  const gl::Buffer* buffer = executor.physical_buffer(list->physical);
  if (!buffer || buffer->size() < graph::kTileListHeaderBytes) return std::nullopt;
  // Read through a staging copy: after a CPU read of the list itself, NVIDIA's driver (580, H100)
  // kept it where the next plan that reused it from the pool ran its tiled passes 2.7x slower
  // (docs/results/tiles.md, "Reading a tile list back").
  unsigned header[4] = {0, 0, 0, 0};
  gl::Buffer staging(sizeof header, nullptr, false);
  glCopyNamedBufferSubData(buffer->id(), staging.id(), 0, 0, sizeof header);
  glGetNamedBufferSubData(staging.id(), 0, sizeof header, header);
  TileListCount c;
  c.capacity = static_cast<unsigned>((buffer->size() - graph::kTileListHeaderBytes) / graph::kTileListEntryBytes);
  c.dispatched = std::min(header[0], c.capacity);
  return c;
}

}  // namespace penumbra::exec
