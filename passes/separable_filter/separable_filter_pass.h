#pragma once
// separable_filter: one axis of a gaussian, box, min, max or depth-bilateral filter over a
// texture of any colour format and channel count. A 2D filter is two passes (axis x, then y);
// docs/writing-a-technique.md shows one in a graph.
#include "exec/pass.h"

namespace penumbra::passes {

exec::PassType separable_filter_pass_type();

}  // namespace penumbra::passes
