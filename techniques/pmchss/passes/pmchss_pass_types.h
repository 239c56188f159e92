#pragma once
// The pass types of the pmchss technique (Sterna 2018), each a compute pass:
//   pmchss_penumbra_mask     reduced-resolution blocker search -> penumbra, then the optional max
//                            filter and Gaussian blur in the same dispatch (section 2.2), or the
//                            average blocker depth for the debug view
//   pmchss_min_downsample    4x4 min of the shadow map (section 2.3)
//   pmchss_shadow_mask       full-resolution soft shadow, penumbra from an in-pass search, the
//                            mask or the min map, optionally checkerboarded (sections 2.1-3)
//   pmchss_checker_upsample  depth-aware fill of the checkerboard's missing pixels (section 3)
#include "exec/pass.h"

namespace penumbra::pmchss {

exec::PassType penumbra_mask_pass_type();
exec::PassType min_downsample_pass_type();
exec::PassType shadow_mask_pass_type();
exec::PassType checker_upsample_pass_type();

}  // namespace penumbra::pmchss
