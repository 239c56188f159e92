#pragma once
#include "exec/pass.h"

namespace penumbra::passes {
exec::PassType hard_mask_pass_type();
}
