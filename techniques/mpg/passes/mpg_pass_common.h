#pragma once
// What the mpg pass types share: parameter declarations used by several of them (a pass type
// declares type, valid range and step only (kernel sizes are odd: step 2 from 3); mpg.json holds
// the user-facing defaults and text), and the depth-aware uniforms of shaders/mpg_common.glsl.
#include <optional>
#include <string>
#include <utility>

#include "exec/pass_decl_builder.h"
#include "techniques/mpg/passes/multipass_kernel.h"

namespace penumbra::mpg {

inline constexpr const char* kShaderDir = "techniques/mpg/shaders/";
inline constexpr int kMaxKernel = 63;  // pixels: largest kernel of any mpg pass
inline constexpr int kMaxPasses = 64;  // graph::kMaxRepeat: what a pass type accepts
// Edge of the tiles of "d_tiles" (shaders/d_tiles.glsl): screen_pass.glsl's work group, which
// the writer and the readers run one of per tile.
inline constexpr int kDTile = 16;

// The input/output pair every screen-space mpg pass has: the distance map (RGBA16F) read through
// a sampler and its next version written with imageStore (ping-pong: the graph renames; with
// `keeps_unwritten`, into the texture of the version two back, graph::SlotDecl::ping_pong).
exec::PassDeclBuilder distance_map_filter(const char* name, const char* description, bool keeps_unwritten = false);

// The kernel_shape input (RGBA16F, same size as the distance map) of passes whose kernels are
// mapped to the receiver's penumbra footprint (shaders/kernel_shape.glsl).
exec::PassDeclBuilder& add_kernel_shape(exec::PassDeclBuilder& b);

// A bilinear clamp-to-edge sampler, made on first use (a context is current in execute()).
GLuint linear_sampler(std::optional<gl::Sampler>& sampler);

// max_kernel [3, 63] pixels, odd; depth_aware + depth_tolerance; the three multi-pass kernel knobs.
exec::PassDeclBuilder& add_max_kernel(exec::PassDeclBuilder& b);
exec::PassDeclBuilder& add_depth_aware(exec::PassDeclBuilder& b);
exec::PassDeclBuilder& add_multipass_kernel(exec::PassDeclBuilder& b);


void set_depth_aware_uniforms(const gl::Program& program, const exec::PassContext& ctx);
KernelSampling kernel_sampling(const exec::PassContext& ctx);
bool progressive_kernel(const exec::PassContext& ctx);
// {"AXIS", "0"} for axis x, {"AXIS", "1"} for y.
std::pair<std::string, std::string> axis_define(const exec::PassContext& ctx);

}  // namespace penumbra::mpg
