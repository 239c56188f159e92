#pragma once
// Percentage-closer soft shadows (Fernando 2005) as two compute passes, so the blocker
// distance is a resource the sandbox can show:
//   pcss_blocker_search  shadow map + G-buffer -> blocker (R32F, mean blocker distance, world
//                        units, 0 = none)
//   pcss_filter          blocker + shadow map + G-buffer -> mask (R16F, 1 = lit)
#include "exec/pass.h"

namespace penumbra::passes {
exec::PassType pcss_blocker_search_pass_type();
exec::PassType pcss_filter_pass_type();
}
