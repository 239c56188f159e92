// Pass 4, multi-pass Gaussian alteration of Cherry & Kooima (sections 3.1-3.2): one blur pass;
// the graph repeats it (`repeat: $max_passes`) and each repetition knows its index, which sets
// its kernel size (fixed, or 3x3 growing by 2 per pass). The taps and their normalised Gaussian
// weights are computed here, per pass, and sent to the shader (section 3.1: "Each offset along
// with its corresponding Gaussian weight is sent to the shader").
// Tiled (slot "tiles" bound, not in the paper): the first pass runs over every pixel, the others
// over the tiles with D > 0 (blur_tiles_pass.cpp) into the texture of the version two back,
// which the graph guarantees (ping-pong output) and which outside those tiles already holds the
// same values (pixels with D = 0 never change): the mask is the untiled one, bit for bit.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glad/gl.h>

#include "passes/shadow_tiles/tiled_dispatch.h"
#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

Status same_resource(const exec::PassContext& ctx, std::string_view a, std::string_view b) {
  std::string ra, rb;
  for (const graph::PlannedBinding& binding : ctx.pass().bindings) {
    if (binding.slot == a) ra = binding.resource;
    if (binding.slot == b) rb = binding.resource;
  }
  if (ra == rb) return {};
  return make_error("pass '" + ctx.pass().name + "': with 'tiles' bound, '" + std::string(a) + "' and '" +
                    std::string(b) + "' must be one resource (each pass reads what the one before wrote), not '" +
                    ra + "' and '" + rb + "'");
}

class MultipassBlurPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const bool dense = kernel_sampling(ctx) == KernelSampling::dense;
    const int iteration = ctx.pass().iteration;
    const bool over_tiles = passes::tiled(ctx) && iteration > 0;
    if (passes::tiled(ctx) && !ctx.bound("tile_passes"))
      return make_error("pass '" + ctx.pass().name + "': slot 'tiles' is bound but 'tile_passes' is not (bind both "
                        "to the tile list's writer: mpg_blur_tiles or the y pass of mpg_dilate)");
    gl::ShaderProgram& p = ctx.program(
        {.compute = std::string(kShaderDir) + "multipass_blur.comp.glsl",
         .defines = {{"DENSE", dense ? "1" : "0"},
                     {"SCREEN_TILED", over_tiles ? "1" : "0"},
                     {"SCREEN_TILE", std::to_string(passes::tiled(ctx) ? ctx.integer("tile_size") : 16)}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input", linear_sampler(linear_));
    if (over_tiles) {
      // Outside the listed tiles the output texture must hold this pass's input: true only when
      // the output is the next version of the input's resource (its ping-pong partner).
      if (Status chain = same_resource(ctx, "input", "output"); !chain) return chain;
      if (Status grid = passes::check_tile_grid(ctx, "tile_passes", "output", ctx.integer("tile_size")); !grid)
        return grid;
      ctx.bind_sampled(p, "u_tile_passes", "tile_passes");
      p.program().set("u_iteration", iteration);
    }
    ctx.bind_sampled(p, "u_kernel_shape", "kernel_shape");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    const gl::Program& prog = p.program();
    const int size = pass_kernel_size(progressive_kernel(ctx), iteration, ctx.integer("max_kernel"));
    prog.set("u_kernel_size", size);
    if (!dense) {
      std::vector<glm::vec4> packed;
      for (const Tap& t : kernel_taps(KernelSampling::poisson, ctx.integer("poisson_taps"), size, iteration))
        packed.emplace_back(t.offset, t.weight, 0.0f);
      glProgramUniform4fv(prog.id(), prog.uniform_location("u_taps"), static_cast<GLsizei>(packed.size()),
                          &packed[0].x);
      prog.set("u_tap_count", static_cast<int>(packed.size()));
    }
    set_depth_aware_uniforms(prog, ctx);
    if (over_tiles) {
      ctx.bind_tile_list(passes::kScreenTileListBinding, "tiles");
      ctx.dispatch_over_tiles(p, "tiles");
    } else {
      ctx.dispatch_over(p, ctx.texture("output"));
    }
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
      "repeated by the graph (Cherry & Kooima 3.1); with 'tiles' and 'tile_passes' bound (from mpg_blur_tiles or "
      "the y pass of mpg_dilate), passes after the first run over the listed tiles only",
      true);
  passes::add_tile_list_slot(b);
  b.sampled("tile_passes", {graph::Format::R16F}, false);
  add_max_kernel(b);
  add_multipass_kernel(b);
  add_depth_aware(b);
  add_kernel_shape(b);
  return b.build<MultipassBlurPass>();
}

}  // namespace penumbra::mpg
