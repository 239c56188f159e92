#pragma once
// What the sspcss pass types share: their common parameter declarations (types and valid
// ranges; the graph JSON holds the user-facing defaults and descriptions) and the uniforms of
// shaders/screen_geometry.glsl, range_term.glsl, penumbra_estimate.glsl, separable_taps.glsl
// and poisson_taps.glsl.
#include <vector>

#include <glm/glm.hpp>

#include "exec/pass.h"
#include "graph/parameters.h"
#include "passes/sampling/poisson_disk.h"

namespace penumbra::sspcss {

// depth_sigma, range_term: the cross-bilateral range term (every filtering pass).
std::vector<graph::ParamDesc> range_params();
// receiver_footprint: the penumbra's screen shape (receiver_footprint.glsl), every pass that
// sizes a kernel.
graph::ParamDesc footprint_param();
// light_size_scale, max_penumbra_px: the search width and the penumbra estimate.
std::vector<graph::ParamDesc> search_params();
// fixed_radius_px: the benchmark/debug override of W_screen (passes that write penumbra_width).
graph::ParamDesc fixed_radius_param();
graph::ParamDesc separable_taps_param();
graph::ParamDesc poisson_taps_param();

// u_view, u_tan_half_fov, u_screen_px, u_d_screen from the frame's camera and screen.
void set_screen_uniforms(const gl::Program& program, const exec::FrameInputs& frame);
// u_footprint.
void set_footprint_uniform(const gl::Program& program, exec::PassContext& ctx);
// u_depth_sigma, u_range_term.
void set_range_uniforms(const gl::Program& program, exec::PassContext& ctx);
// The light (shadow_common.glsl), u_light_size_scale, u_max_penumbra_px.
[[nodiscard]] Status set_penumbra_uniforms(const gl::Program& program, exec::PassContext& ctx);
// u_fixed_radius_px (passes that write penumbra_width).
void set_fixed_radius_uniform(const gl::Program& program, exec::PassContext& ctx);
// u_taps from separable_taps.
void set_separable_uniforms(const gl::Program& program, exec::PassContext& ctx);
// The 2D Poisson disk of the Poisson filter (section 2: "a 2D random Poisson disk as the domain
// filter"): the first poisson_taps points of this sequence in the unit disk, rotated per pixel in
// the shader (poisson_taps.glsl). The seed is fixed so images and tests are reproducible.
inline constexpr passes::PoissonDiskOptions kPoissonDisk{.seed = 0x2545F491u};

// u_poisson[], u_poisson_taps from poisson_taps; `disk` caches the pass's point set (regenerated
// when the tap count changes).
void set_poisson_uniforms(const gl::Program& program, exec::PassContext& ctx, std::vector<glm::vec2>& disk);

}  // namespace penumbra::sspcss
