#pragma once
#include "exec/pass.h"

namespace penumbra::passes {
exec::PassType shadow_map_pass_type();
}
