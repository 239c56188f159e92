#pragma once
// The pass types of the esm technique (Bujnak, extended shadow maps):
//   esm_depth             raster: the depth map of every face into the depth attachment; the
//                         extended map's two R32F channels cleared to each texel's defaults
//                         (section 4)
//   esm_silhouette_quads  raster or compute: the silhouette quads of every mesh, MAX-blended into
//                         the extended map, or overwriting it (the paper's two-pass fallback's
//                         first pass), or written texel by texel with atomic MAX (section 4.1)
//   esm_mask              compute: the shadow test into the frame's shadow_mask (section 3.2)
//   esm_debug             compute: the edge-distance channel (texels) and the silhouette mask as
//                         single-channel textures for the viewer
#include "exec/pass.h"

namespace penumbra::esm {

exec::PassType depth_pass_type();
exec::PassType silhouette_quad_pass_type();
exec::PassType mask_pass_type();
exec::PassType debug_pass_type();

}  // namespace penumbra::esm
