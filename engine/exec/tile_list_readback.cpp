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
  unsigned header[4] = {0, 0, 0, 0};
  glGetNamedBufferSubData(buffer->id(), 0, sizeof header, header);
  TileListCount c;
  c.capacity = static_cast<unsigned>((buffer->size() - graph::kTileListHeaderBytes) / graph::kTileListEntryBytes);
  c.dispatched = std::min(header[0], c.capacity);
  return c;
}

}  // namespace penumbra::exec
