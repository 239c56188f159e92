#pragma once
// Pass type "reference_raytraced": exact area-light visibility traced on the CPU with Embree
// (raytraced_reference.h) from the frame's own G-buffer, uploaded into shadow_mask. It traces
// only when the reset rule (reference_frame_key.h) says the inputs changed; other frames upload
// the kept result, so the sandbox shows it "on demand" at the cost of one trace per view.
#include "exec/pass.h"

namespace penumbra::reference {
exec::PassType raytraced_reference_pass_type();
}
