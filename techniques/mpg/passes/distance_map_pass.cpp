// Pass 2 of Cherry & Kooima (section 3): the distance map (S, D, view depth) from one shadow-map
// comparison per pixel. The mapping from occluder distance to D is in distance_map.comp.glsl.
#include <cmath>
#include <optional>

#include <glad/gl.h>

#include "passes/common/shadow_receiver_decl.h"
#include "passes/common/shadow_uniforms.h"
#include "passes/shadow_tiles/tiled_dispatch.h"
#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

using graph::Format;

const char* alteration_define(const std::string& alteration) {
  if (alteration == "pcf") return "0";
  if (alteration == "gaussian") return "1";
  return "2";  // multipass
}

const char* shadow_test_define(const std::string& test) {
  if (test == "nearest") return "0";
  if (test == "bilinear") return "1";
  return "2";  // footprint
}

class DistanceMapPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const std::string alteration = ctx.enumeration("alteration");
    gl::ShaderProgram& p = ctx.program(
        {.compute = std::string(kShaderDir) + "distance_map.comp.glsl",
         .defines = {{"MAPPING", ctx.enumeration("mapping") == "physical" ? "1" : "0"},
                     {"ALTERATION", alteration_define(alteration)},
                     {"SHADOW_TEST", shadow_test_define(ctx.enumeration("shadow_test"))},
                     {"D_TILES", ctx.bound("d_tiles") ? "1" : "0"}}});
    if (!p.valid()) return *p.last_error();
    if (ctx.bound("d_tiles")) {
      if (Status grid = passes::check_tile_grid(ctx, "d_tiles", "distance_map", kDTile); !grid) return grid;
      ctx.bind_image(2, "d_tiles", GL_WRITE_ONLY);
    }
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    if (!nearest_) nearest_.emplace(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp);
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", nearest_->id());
    ctx.bind_image(0, "distance_map", GL_WRITE_ONLY);
    ctx.bind_image(1, "kernel_shape", GL_WRITE_ONLY);
    const gl::Program& prog = p.program();
    const exec::FrameInputs& frame = ctx.frame();
    if (Status s = passes::set_shadow_uniforms(prog, frame, passes::SixFaces::read); !s) return s;
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    prog.set("u_distance_power", ctx.real("distance_power"));
    prog.set("u_distance_multiplier", ctx.real("distance_multiplier"));
    prog.set("u_light_size_scale", ctx.real("light_size_scale"));
    prog.set("u_footprint_spread", ctx.real("footprint_spread"));
    // Pixels per world unit at view depth 1 (the receiver's depth divides it in the shader).
    prog.set("u_focal_px", static_cast<float>(frame.screen_h) / (2.0f * std::tan(0.5f * frame.camera.fov_y)));
    prog.set("u_view_proj", frame.projection() * frame.view());
    prog.set("u_anisotropic", ctx.boolean("anisotropic") ? 1 : 0);
    const int max_kernel = ctx.integer("max_kernel"), max_passes = ctx.integer("max_passes");
    prog.set("u_max_kernel", static_cast<float>(max_kernel));
    prog.set("u_max_passes", max_passes);
    if (alteration == "multipass") {
      // The physical mapping inverts the blur passes' summed variance (multipass_kernel.h).
      std::vector<float> variance = cumulative_pass_variance(kernel_sampling(ctx), ctx.integer("poisson_taps"),
                                                             progressive_kernel(ctx), max_kernel, max_passes);
      glProgramUniform1fv(prog.id(), prog.uniform_location("u_pass_variance"), static_cast<GLsizei>(variance.size()),
                          variance.data());
    }
    gl::Texture& out = ctx.texture("distance_map");
    ctx.dispatch_over(p, out.width(), out.height());
    return {};
  }

 private:
  std::optional<gl::Sampler> nearest_;  // raw depths (no comparison), made on first use
};

}  // namespace

exec::PassType distance_map_pass_type() {
  exec::PassDeclBuilder b = passes::shadow_receiver_pass(
      "mpg_distance_map",
      "mpg pass 2: hard shadow bit S and filter control D from the occluder distance (Cherry & Kooima 3.1)");
  b.image_out("distance_map", {Format::RGBA16F})
      .image_out("kernel_shape", {Format::RGBA16F})
      .image_out("d_tiles", {Format::R8}, false)
      .same_size({"depth", "normal", "distance_map", "kernel_shape"})
      .enumeration("shadow_test", "footprint", {"footprint", "bilinear", "nearest"},
                   "Pass 2's S: footprint = the shadow map prefiltered in light space by a Gaussian of the penumbra's "
                   "spread, at most footprint_spread pixels, the screen passes adding the rest (physical mapping; "
                   "bilinear with the paper's); bilinear = the 2x2 nearest texels compared and weighted bilinearly; "
                   "nearest = the paper's bit from one texel")
      .real("footprint_spread", 0.5, 0.1, 4.0, "pixels",
            "Footprint S: the widest light-space prefilter, as a spread (standard deviation) on screen; narrower "
            "penumbrae are made by it alone (0.5: the most that 25 taps sample without visible steps)")
      .enumeration("mapping", "physical", {"physical", "paper"},
                   "Occluder distance to D: physical = PCSS penumbra width from the scene light's size, in pixels "
                   "(section 6); paper = (distance / light depth range)^Dp * Dm (section 3.2)")
      .real("distance_power", 3.0, 0.1, 10.0, "",
            "Dp of the paper mapping: exponent of the normalised occluder distance (Figure 5: 3.0; 1.9 for the "
            "single-pass Gaussian)")
      .real("distance_multiplier", 200.0, 0.0, 100000.0, "",
            "Dm of the paper mapping: D = (distance / light depth range)^Dp * Dm, in kernel pixels (PCF, Gaussian) or "
            "passes (multi-pass) (Figure 5: 200)")
      .real("light_size_scale", 1.0, 0.0, 10.0, "",
            "Physical mapping: multiplier on the scene light's emitter diameter (the one PCSS and the reference use)")
      .boolean("anisotropic", true,
               "Shape every screen-space kernel like the receiver's penumbra footprint on screen (stretched along the "
               "light, foreshortened by the view; at most 6:1); off: round kernels, as in the paper")
      .enumeration("alteration", "multipass", {"pcf", "gaussian", "multipass"},
                   "Pass 4 (section 3.1): PCF of S with a D-sized box, a single-pass separable Gaussian of size D, or "
                   "multi-pass Gaussian blurs counted down by D")
      .integer("max_passes", 10, 1, kMaxPasses, "",
               "Multi-pass: number of blur passes in the graph (repeat); D counts down one per pass (Figure 5G: 10; "
               "hard bound 32)")
      .real("depth_bias", 0.0005, 0.0, 0.05, "window depth",
            "Subtracted from the receiver depth before the hard shadow comparison (pass 2)");
  add_max_kernel(b);
  add_multipass_kernel(b);
  return b.build<DistanceMapPass>();
}

}  // namespace penumbra::mpg
