#pragma once
// The pass types every frame and most techniques use (one folder each under passes/).
#include "exec/pass.h"

namespace penumbra {

void register_shared_passes(exec::PassLibrary& library);

}  // namespace penumbra
