#pragma once
#include "exec/pass.h"

namespace penumbra::passes {
exec::PassType gbuffer_pass_type();
}
