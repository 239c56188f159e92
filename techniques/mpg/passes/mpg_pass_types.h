#pragma once
// The pass types of the mpg technique (Cherry & Kooima, multi-pass Gaussian contact-hardening
// soft shadows), each a compute pass over the screen-size distance map (layout in
// shaders/mpg_common.glsl):
//   mpg_distance_map      pass 2: hard shadow bit S and filter control D per pixel
//   mpg_umbra_early_out   section 5: D = 0 deep inside umbrae (one axis of a separable test)
//   mpg_dilate            pass 3: Gaussian dilation of D into lit pixels (one axis)
//   mpg_pcf_filter        pass 4, PCF alteration: box of size D
//   mpg_gaussian_filter   pass 4, single-pass Gaussian alteration (one axis)
//   mpg_multipass_blur    pass 4, multi-pass alteration: one blur pass, repeated by the graph
//   mpg_resolve_mask      pass 5: shadow_mask = 1 - S
//   mpg_distance_view     debug: D as a colour gradient
//   mpg_penumbra_view     debug: Figure 4, penumbra marked, umbra shaded
#include "exec/pass.h"

namespace penumbra::mpg {

exec::PassType distance_map_pass_type();
exec::PassType umbra_early_out_pass_type();
exec::PassType dilate_pass_type();
exec::PassType pcf_filter_pass_type();
exec::PassType gaussian_filter_pass_type();
exec::PassType blur_tiles_pass_type();
exec::PassType multipass_blur_pass_type();
exec::PassType resolve_mask_pass_type();
exec::PassType distance_view_pass_type();
exec::PassType penumbra_view_pass_type();

}  // namespace penumbra::mpg
