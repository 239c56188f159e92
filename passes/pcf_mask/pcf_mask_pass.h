#pragma once
#include "exec/pass.h"

namespace penumbra::passes {
// "pcf_mask": fixed-kernel percentage-closer filtering (box or Vogel disk) into a shadow mask.
exec::PassType pcf_mask_pass_type();
}
