#pragma once
// The frame every technique runs inside. compose_frame_graph() wraps a technique's graph:
//
//   prologue  gbuffer (type "gbuffer"): scene + camera ->
//               gbuffer_depth    R32F     screen  linear view depth (> 0), 0 where no geometry
//               gbuffer_normal   RG16     screen  world-space unit normal, octahedral
//               gbuffer_albedo   RGBA8    screen  base colour
//               gbuffer_zbuffer  DEPTH32F screen  the depth test's buffer (not for techniques)
//             A receiver's position is rebuilt from its view depth and the camera
//             (passes/gbuffer/gbuffer_read.glsl): 8 bytes per pixel for position and normal.
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
inline constexpr const char* kViewDepth = "gbuffer_depth";  // R32F linear view depth, 0 = background

// Imported and gbuffer resources a technique may re-declare identically; a conflicting
// declaration (same name, different kind/format/size) is an error naming the resource.
Result<graph::GraphDesc> compose_frame_graph(const graph::GraphDesc& technique);

// A technique graph: one that binds a resource the frame provides (scene, camera, light,
// gbuffer_*) without declaring it. `penumbra graph` composes such a graph by itself.
bool reads_frame_resources(const graph::GraphDesc& graph);

// Resources the frame no longer provides, with what replaced them; binding one is an error
// that names the replacement.
struct RemovedFrameResource {
  const char* name;
  const char* replacement;
};
inline constexpr RemovedFrameResource kRemovedFrameResources[] = {
    {"gbuffer_position",
     "bind 'gbuffer_depth' (R32F linear view depth) and rebuild the position with gbuffer_position() "
     "from passes/gbuffer/gbuffer_read.glsl (docs/writing-a-technique.md, \"The frame contract\")"},
};

}  // namespace penumbra::technique
