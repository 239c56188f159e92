#pragma once
// The pass types of the sspcss technique (MohammadBagher, Kautz, Holzschuch, Soler), all compute
// passes over the screen:
//   sspcss_prepare                 hard shadow + projected shadow map (section 1, preparation)
//   sspcss_blocker_search_x / _y   separable edge-aware blocker search, rows then columns, and the
//                                  penumbra estimate (section 1; Gaussian of section 2)
//   sspcss_blocker_search_poisson  the same over a Poisson disk, one pass (section 2)
//   sspcss_filter_x / _y           separable cross-bilateral Gaussian of the hard shadow, rows then
//                                  columns, diameter W_screen (sections 1, 2)
//   sspcss_filter_poisson          cross-bilateral Poisson filter of the hard shadow (section 2)
// The graph (sspcss.json) picks the separable or the Poisson passes with `enabled`.
#include "exec/pass.h"

namespace penumbra::sspcss {

exec::PassType prepare_pass_type();
exec::PassType blocker_search_x_pass_type();
exec::PassType blocker_search_y_pass_type();
exec::PassType blocker_search_poisson_pass_type();
exec::PassType filter_x_pass_type();
exec::PassType filter_y_pass_type();
exec::PassType filter_poisson_pass_type();

}  // namespace penumbra::sspcss
