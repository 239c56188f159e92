#pragma once
// The frame every technique runs inside. compose_frame_graph() wraps a technique's graph:
//
//   prologue  gbuffer (type "gbuffer"): scene + camera ->
//               gbuffer_depth    DEPTH32F screen
//               gbuffer_normal   RGBA16F  screen  world-space unit normal, w = 1 on geometry
//               gbuffer_position RGBA32F  screen  world position, w = linear view depth (> 0),
//                                                 w = 0 where no geometry (background)
//               gbuffer_albedo   RGBA8    screen  base colour
//   technique its passes, reading any of the above plus the imported scene/camera/light, and
//             writing `shadow_mask` (R8, R16F or R32F, screen size; 1 = lit, 0 = umbra)
//   epilogue  lighting (type "lighting"): Lambert + ambient with base colour, shadowed by
//             shadow_mask, tone mapped -> `color` RGBA8 screen
//
// The frame's outputs are `color` and `shadow_mask`, plus the technique's own outputs (debug
// resources such as a penumbra mask stay alive when listed there).
#include "graph/graph_desc.h"
#include "util/error.h"

namespace penumbra::technique {

inline constexpr const char* kShadowMask = "shadow_mask";
inline constexpr const char* kColor = "color";

// Imported and gbuffer resources a technique may re-declare identically; a conflicting
// declaration (same name, different kind/format/size) is an error naming the resource.
Result<graph::GraphDesc> compose_frame_graph(const graph::GraphDesc& technique);

// A technique graph: one that binds a resource the frame provides (scene, camera, light,
// gbuffer_*) without declaring it. `penumbra graph` composes such a graph by itself.
bool reads_frame_resources(const graph::GraphDesc& graph);

}  // namespace penumbra::technique
