#include "techniques/mpg/passes/mpg_pass_common.h"

namespace penumbra::mpg {

using graph::Format;

exec::PassDeclBuilder distance_map_filter(const char* name, const char* description, bool keeps_unwritten) {
  exec::PassDeclBuilder b(name);
  b.describe(description).sampled("input", {Format::RGBA16F});
  if (keeps_unwritten) b.image_out_ping_pong("output", {Format::RGBA16F});
  else b.image_out("output", {Format::RGBA16F});
  b.same_size({"input", "output"});
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
  return b.integer("max_kernel", 19, 3, kMaxKernel, "pixels",
                   "Largest kernel, odd: PCF and Gaussian sizes are clamped to it; the multi-pass kernel is this size "
                   "(fixed) or grows to it from 3x3 (Figure 5: 19)")
      .step(2);
}

exec::PassDeclBuilder& add_depth_aware(exec::PassDeclBuilder& b) {
  return b.boolean("depth_aware", true,
                   "Leave out filter taps on another surface (farther than depth_tolerance from the centre receiver's "
                   "plane); not in the paper, which filters across depth edges")
      .real("depth_tolerance", 0.1, 0.001, 10.0, "",
            "Depth-aware taps: largest distance of a tap from the centre receiver's plane, as a fraction of the "
            "centre's view depth");
}

exec::PassDeclBuilder& add_multipass_kernel(exec::PassDeclBuilder& b) {
  return b.enumeration("kernel_mode", "progressive", {"progressive", "fixed"},
                       "Multi-pass kernel size per pass: progressive = 3x3 on the first pass, 2 pixels wider each pass "
                       "up to max_kernel; fixed = max_kernel every pass")
      .integer("poisson_taps", 20, 1, 64, "",
               "Multi-pass: taps per blur pass, the first N of 64 precomputed Poisson-disk points in [-1, 1]^2, the "
               "first at the origin (Figure 5G: 20)")
      .enumeration("kernel_sampling", "poisson", {"poisson", "dense"},
                   "Multi-pass: poisson_taps Poisson points, or every texel of the kernel (the 'entire Gaussian' of "
                   "Figure 7; KS^2 taps, a reference, slow)");
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
