#pragma once
// A handful of GENERIC pass type declarations (no GL behind them) for the graph compiler's
// tests and benchmark: they exercise what no shipped pass type does (storage buffers, in-place
// repeats, side-effect composites). Real pass types live next to their GL code; the documented
// examples (docs/graph-examples) use those.
//
//   shadow_map      raster: scene, light (imported) -> depth (DEPTH32F, depth attachment)
//   depth_prepass   raster: scene, camera (imported) -> depth (DEPTH32F)
//   blocker_search  compute: shadow_map, depth (sampled) -> blocker (R16F/R32F/RG16F, image store)
//   penumbra_filter compute: shadow_map, depth, blocker?, tiles? -> mask (R8/R16F, image store)
//   tile_classify   compute: depth -> tiles (buffer, storage buffer)
//   blur            compute: input (sampled) -> output (image store); same size
//   blur_in_place   compute: image (read_write, image load/store)
//   accumulate      compute: sample (sampled) + history (persistent, read_write)
//   composite       raster: mask (sampled) -> target (imported output); side effect
#include "graph/pass_types.h"

namespace penumbra::graph {

void register_generic_pass_types(PassTypeRegistry& registry);

}  // namespace penumbra::graph
