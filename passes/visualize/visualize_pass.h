#pragma once
#include "exec/pass.h"

namespace penumbra::passes {
// "visualize": a single-channel texture (R8, R16F, R32F, DEPTH32F) -> RGBA8 through a grey or
// heat colour map over [min, max]; what the sandbox and CLI use to show debug resources.
exec::PassType visualize_pass_type();
}
