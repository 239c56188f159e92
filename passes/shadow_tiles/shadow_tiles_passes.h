#pragma once
// The shared tile classifier every filtering technique runs before its filter passes, so those
// passes work only where the penumbra is (tiled_dispatch.h):
//   "shadow_planes": each block of the shadow map as a plane and the range of depths about it
//                    (RGBA32F: shadow/8 for a filter a few texels wide, shadow/32 for PCSS's search);
//   "shadow_tiles":  each screen tile lit, umbra or penumbra (an R8 texel per tile) and the
//                    list of penumbra tiles.
#include "exec/pass.h"

namespace penumbra::passes {
exec::PassType shadow_planes_pass_type();
exec::PassType shadow_tiles_pass_type();
}  // namespace penumbra::passes
