#pragma once
// The inputs every pass that shades G-buffer receivers against the shadow map declares: the
// G-buffer position and normal, the shadow map and the frame's light.
#include "exec/pass_decl_builder.h"

namespace penumbra::passes {

// A declaration named `name` with those four inputs; the caller adds its outputs and parameters.
exec::PassDeclBuilder shadow_receiver_pass(const char* name, const char* description);

}  // namespace penumbra::passes
