// Pass 4, multi-pass Gaussian alteration of Cherry & Kooima (sections 3.1-3.2): one blur pass;
// the graph repeats it (`repeat: $max_passes`) and each repetition knows its index, which sets
// its kernel size (fixed, or 3x3 growing by 2 per pass). The taps and their normalised Gaussian
// weights are computed here, per pass, and sent to the shader (section 3.1: "Each offset along
// with its corresponding Gaussian weight is sent to the shader").
#include <optional>
#include <vector>

#include <glad/gl.h>

#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

class MultipassBlurPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const bool dense = kernel_sampling(ctx) == KernelSampling::dense;
    gl::ShaderProgram& p = ctx.program({.compute = std::string(kShaderDir) + "multipass_blur.comp.glsl",
                                        .defines = {{"DENSE", dense ? "1" : "0"}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input", linear_sampler(linear_));
    ctx.bind_sampled(p, "u_kernel_shape", "kernel_shape");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    const gl::Program& prog = p.program();
    const int size = pass_kernel_size(progressive_kernel(ctx), ctx.pass().iteration, ctx.integer("max_kernel"));
    prog.set("u_kernel_size", size);
    if (!dense) {
      std::vector<glm::vec4> packed;
      for (const Tap& t : kernel_taps(KernelSampling::poisson, ctx.integer("poisson_taps"), size))
        packed.emplace_back(t.offset, t.weight, 0.0f);
      glProgramUniform4fv(prog.id(), prog.uniform_location("u_taps"), static_cast<GLsizei>(packed.size()),
                          &packed[0].x);
      prog.set("u_tap_count", static_cast<int>(packed.size()));
    }
    set_depth_aware_uniforms(prog, ctx);
    ctx.dispatch_over(p, ctx.texture("output"));
    return {};
  }

 private:
  std::optional<gl::Sampler> linear_;  // bilinear taps at fractional offsets; made on first use
};

}  // namespace

exec::PassType multipass_blur_pass_type() {
  exec::PassDeclBuilder b = distance_map_filter(
      "mpg_multipass_blur",
      "mpg pass 4, multi-pass Gaussian: one Poisson-disk Gaussian blur of S where D > 0, then D - 1; "
      "repeated by the graph (Cherry & Kooima 3.1)");
  add_max_kernel(b);
  add_multipass_kernel(b);
  add_depth_aware(b);
  add_kernel_shape(b);
  return b.build<MultipassBlurPass>();
}

}  // namespace penumbra::mpg
