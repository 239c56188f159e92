// One axis of a separable single-channel filter: the min filter and small blur of the min-filter
// variant (Sterna 2018, section 2.3). (The penumbra mask's max filter and blur, section 2.2, run
// inside the mask's own dispatch: penumbra_mask.comp.glsl.)
#include <algorithm>
#include <cmath>

#include "exec/pass_decl_builder.h"
#include "gl/texture.h"
#include "techniques/pmchss/passes/pmchss_pass_common.h"
#include "techniques/pmchss/passes/pmchss_pass_types.h"

namespace penumbra::pmchss {
namespace {

using graph::Format;

const char* mode_define(const std::string& mode) {
  if (mode == "max") return "1";
  if (mode == "min") return "2";
  if (mode == "copy") return "3";
  return "0";  // gaussian
}

// radius_uv > 0 sizes the filter in shadow-map UV (the min filter covers the blocker search
// region, "region of max penumbra size", section 2.3): ceil(radius_uv x scale x width) texels.
int radius_texels(exec::PassContext& ctx, int width) {
  double uv = ctx.real("radius_uv");
  if (uv <= 0.0) return ctx.integer("radius");
  double texels = std::ceil(uv * ctx.real("radius_uv_scale") * width);
  return static_cast<int>(std::clamp(texels, 1.0, 16.0));
}

class SeparableFilterPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::Texture& out = ctx.texture("output");
    const char* format = out.format() == gl::Format::R32F ? "r32f" : "r16f";
    gl::ShaderProgram& p = ctx.program(
        {.compute = "techniques/pmchss/shaders/separable_filter.comp.glsl",
         .defines = {{"MODE", mode_define(ctx.enumeration("mode"))}, {"IMAGE_FORMAT", format}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_input", "input");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    bool vertical = ctx.enumeration("axis") == "y";
    p.program().set("u_axis", vertical ? glm::ivec2(0, 1) : glm::ivec2(1, 0));
    p.program().set("u_radius", radius_texels(ctx, out.width()));
    p.program().set("u_sigma", ctx.real("sigma"));
    ctx.dispatch_over(p, out.width(), out.height());
    return {};
  }
};

}  // namespace

exec::PassType separable_filter_pass_type() {
  return exec::PassDeclBuilder("pmchss_separable_filter")
      .describe("One axis of a separable gaussian / max / min filter (Sterna 2018, 2.2-2.3)")
      .sampled("input", {Format::R16F, Format::R32F})
      .image_out("output", {Format::R16F, Format::R32F})
      .same_size({"input", "output"})
      .param(enum_param("mode", "gaussian", {"gaussian", "max", "min", "copy"}, "Filter kind"))
      .param(enum_param("axis", "x", {"x", "y"}, "Filter direction"))
      .required()
      .param(int_param("radius", 3, 0, 16, "texels", "Taps each side (7x7 = radius 3)"))
      .param(real_param("sigma", 3.0, 0.1, 16.0, "texels", "Gaussian standard deviation"))
      .param(real_param("radius_uv", 0.0, 0.0, 0.05, "shadow-map UV",
                        "When > 0: radius = ceil(radius_uv x radius_uv_scale x width), 1..16 texels"))
      .param(real_param("radius_uv_scale", 1.0, 1.0, 2.0, "", "Multiplies radius_uv"))
      .build<SeparableFilterPass>();
}

}  // namespace penumbra::pmchss
