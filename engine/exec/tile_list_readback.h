#pragma once
// How much of its tile list a pass ran over in the last frame: the list's header read back
// (the tiles appended) over its capacity (every tile of the grid). For measurements only
// (`penumbra bench`): the read-back waits for the GPU.
#include <optional>

#include "exec/executor.h"

namespace penumbra::exec {

struct TileListCount {
  unsigned dispatched = 0;  // tiles appended by the writer, i.e. work groups dispatched
  unsigned capacity = 0;    // tiles of the grid
  double fraction() const { return capacity > 0 ? static_cast<double>(dispatched) / capacity : 0.0; }
};

// nullopt when `pass` (one of the executor's plan) did not dispatch over a tile list last frame.
std::optional<TileListCount> dispatched_tiles(const Executor& executor, const graph::PlannedPass& pass);

}  // namespace penumbra::exec
