#pragma once
#include "exec/pass.h"

namespace penumbra::passes {
exec::PassType lighting_pass_type();
}
