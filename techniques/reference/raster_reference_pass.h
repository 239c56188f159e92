#pragma once
// Pass type "reference_raster": ground truth by accumulating the hard visibility of many shadow
// maps rendered from stratified points on the emitter disk (scene::light_sample_points, the
// sampling the ray tracer uses), `maps_per_frame` per frame into a persistent R32F sum, until
// `samples` maps are in. shadow_mask = sum / count. Reset rule: reference_frame_key.h.
#include "exec/pass.h"

namespace penumbra::reference {
exec::PassType raster_reference_pass_type();
}
