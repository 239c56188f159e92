#pragma once
// What the pmchss pass types share: their common parameter declarations, the uniforms of
// shaders/pmchss_common.glsl, the shader defines derived from parameters, and the check that
// the shadow map is large enough for the blocker search.
#include <string>
#include <utility>
#include <vector>

#include "exec/pass.h"
#include "graph/parameters.h"

namespace penumbra::pmchss {

// Declaration helpers. The pass types hold the one description of their parameters; pmchss.json
// exposes them, stating only its own defaults (docs/graph-format.md "Parameters").
using graph::bool_param;
using graph::enum_param;
using graph::int_param;
using graph::real_param;

// Parameters every pass that searches blockers or maps a penumbra takes: shadow_filter_max_size,
// penumbra_kernel_scale, penumbra_mapping, k, depth_bias, receiver_plane_bias.
std::vector<graph::ParamDesc> penumbra_params();
// Two of them, also taken by the min-filter passes.
graph::ParamDesc shadow_filter_max_size_param();
graph::ParamDesc penumbra_kernel_scale_param();

// Sets u_shadow_filter_max_size, u_search_radius, u_penumbra_k, u_depth_bias,
// u_receiver_plane and the light uniforms (shadow_common.glsl).
[[nodiscard]] Status set_pmchss_uniforms(const gl::Program& program, exec::PassContext& ctx);

// PENUMBRA_MAPPING: 0 paper, 1 physical, 2 fixed (pmchss_common.glsl).
std::pair<std::string, std::string> mapping_define(exec::PassContext& ctx);

// The smallest shadow map the blocker search can use: its radius,
// penumbra_kernel_scale x shadow_filter_max_size (shadow-map UV), must cover at least one
// texel, or every tap reads the receiver's own texel and the penumbra is noise. The Error
// names the parameters, their values and the smallest shadow size that would work.
Status check_search_covers_texel(exec::PassContext& ctx, int shadow_size);

}  // namespace penumbra::pmchss
