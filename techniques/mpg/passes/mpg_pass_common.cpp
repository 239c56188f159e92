#include "techniques/mpg/passes/mpg_pass_common.h"

namespace penumbra::mpg {

using graph::Format;

exec::PassDeclBuilder distance_map_filter(const char* name, const char* description) {
  exec::PassDeclBuilder b(name);
  b.describe(description)
      .sampled("input", {Format::RGBA16F})
      .image_out("output", {Format::RGBA16F})
      .same_size({"input", "output"});
  return b;
}

exec::PassDeclBuilder& add_kernel_shape(exec::PassDeclBuilder& b) {
  return b.sampled("kernel_shape", {Format::RGBA16F}).same_size({"input", "kernel_shape"});
}

GLuint linear_sampler(std::optional<gl::Sampler>& sampler) {
  if (!sampler) sampler.emplace(gl::Sampler::Filter::linear, gl::Sampler::Wrap::clamp);
  return sampler->id();
}

exec::PassDeclBuilder& add_max_kernel(exec::PassDeclBuilder& b) {
  return b.integer("max_kernel", 19, 3, kMaxKernel, "pixels", "Largest filter kernel (odd)").step(2);
}

exec::PassDeclBuilder& add_depth_aware(exec::PassDeclBuilder& b) {
  return b.boolean("depth_aware", true, "Leave out taps on another surface")
      .real("depth_tolerance", 0.1, 0.001, 10.0, "", "Relative view-depth difference of one surface");
}

exec::PassDeclBuilder& add_multipass_kernel(exec::PassDeclBuilder& b) {
  return b.enumeration("kernel_mode", "progressive", {"progressive", "fixed"}, "Kernel size per blur pass")
      .integer("poisson_taps", 20, 1, 64, "", "Poisson-disk taps per blur pass")
      .enumeration("kernel_sampling", "poisson", {"poisson", "dense"}, "Poisson taps or every kernel texel");
}

void set_depth_aware_uniforms(const gl::Program& program, const exec::PassContext& ctx) {
  program.set("u_depth_aware", ctx.boolean("depth_aware") ? 1 : 0);
  program.set("u_depth_tolerance", ctx.real("depth_tolerance"));
}

KernelSampling kernel_sampling(const exec::PassContext& ctx) {
  return ctx.enumeration("kernel_sampling") == "dense" ? KernelSampling::dense : KernelSampling::poisson;
}

bool progressive_kernel(const exec::PassContext& ctx) { return ctx.enumeration("kernel_mode") == "progressive"; }

std::pair<std::string, std::string> axis_define(const exec::PassContext& ctx) {
  return {"AXIS", ctx.enumeration("axis") == "y" ? "1" : "0"};
}

}  // namespace penumbra::mpg
