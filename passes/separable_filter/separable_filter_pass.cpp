// One axis of a separable filter, any colour format: the output's image qualifier is chosen from
// the bound texture (IMAGE_FORMAT), so the shader's declaration and the texture always agree.
// pm-CHSS's min-filter variant runs its min filter and blur with it (Sterna 2018, section 2.3);
// plugins use it for moment and variance maps.
#include "passes/separable_filter/separable_filter_pass.h"

#include <algorithm>
#include <cmath>

#include "exec/pass_decl_builder.h"
#include "gl/texture.h"
#include "graph/parameters.h"
#include "passes/common/shadow_uniforms.h"

namespace penumbra::passes {
namespace {

using graph::Format;

// MODE in separable_filter.comp.glsl, in the order of the `mode` parameter's choices.
const std::vector<std::string>& modes() {
  static const std::vector<std::string> m{"gaussian", "max", "min", "copy", "box", "bilateral"};
  return m;
}

std::string mode_define(const std::string& mode) {
  const auto& m = modes();
  return std::to_string(std::find(m.begin(), m.end(), mode) - m.begin());
}


// The most taps each side, whichever parameter sizes the filter (MAX_RADIUS in the shader).
constexpr int kMaxRadius = 16;

// radius_uv > 0 sizes the filter in the UV of a texture covering the shadow map (pm-CHSS's min filter covers
// the blocker search region, "region of max penumbra size", section 2.3): ceil(radius_uv x
// scale x width) texels, 1..kMaxRadius.
int radius_texels(exec::PassContext& ctx, int width) {
  const double uv = ctx.real("radius_uv");
  if (uv <= 0.0) return ctx.integer("radius");
  const double texels = std::ceil(uv * ctx.real("radius_uv_scale") * width);
  return static_cast<int>(std::clamp(texels, 1.0, double(kMaxRadius)));
}

class SeparableFilterPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const std::string& mode = ctx.enumeration("mode");
    const bool bilateral = mode == "bilateral";
    // penumbra_height > 0: the shader sizes the gaussian from the frame's light (shadow_common.glsl).
    const double penumbra_height = ctx.real("penumbra_height");
    const bool sigma_from_light = penumbra_height > 0.0 && (mode == "gaussian" || bilateral);
    if (bilateral && !ctx.bound("depth"))
      return make_error("separable_filter: mode 'bilateral' weighs taps by depth: bind the 'depth' slot",
                        ErrorKind::bad_input);
    gl::Texture& out = ctx.texture("output");
    gl::ShaderProgram& p = ctx.program(
        {.compute = "passes/separable_filter/separable_filter.comp.glsl",
         .defines = {{"MODE", mode_define(mode)},
                     {"IMAGE_FORMAT", graph::image_format_qualifier(out.format())},
                     {"MAX_RADIUS", std::to_string(kMaxRadius)},
                     {"SIGMA_FROM_LIGHT", sigma_from_light ? "1" : "0"}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_input", "input");
    if (bilateral) ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    p.program().set("u_axis", ctx.enumeration("axis") == "y" ? glm::ivec2(0, 1) : glm::ivec2(1, 0));
    p.program().set("u_radius", radius_texels(ctx, out.width()));
    p.program().set("u_sigma", ctx.real("sigma"));
    p.program().set("u_depth_sigma", ctx.real("depth_sigma"));
    if (sigma_from_light) {
      if (Status s = set_shadow_uniforms(p.program(), ctx.frame()); !s) return s;
      p.program().set("u_penumbra_height", static_cast<float>(penumbra_height));
    }
    ctx.dispatch_over(p, out.width(), out.height());
    return {};
  }
};

}  // namespace

exec::PassType separable_filter_pass_type() {
  using graph::enum_param;
  using graph::int_param;
  using graph::real_param;
  return exec::PassDeclBuilder("separable_filter")
      .describe("One axis of a gaussian / box / min / max / depth-bilateral filter, any colour format (compute)")
      .sampled("input", graph::colour_formats())
      .sampled("depth", {Format::R16F, Format::R32F, Format::DEPTH32F}, false)
      .image_out("output", graph::colour_formats())
      .same_size({"input", "output", "depth"})
      .param(enum_param("mode", "gaussian", modes(), "Filter kind (bilateral needs the depth slot)"))
      .param(enum_param("axis", "x", {"x", "y"}, "Filter direction"))
      .required()
      .param(int_param("radius", 3, 0, kMaxRadius, "texels", "Taps each side (7x7 = radius 3)"))
      .param(real_param("sigma", 3.0, 0.1, 16.0, "texels", "Gaussian standard deviation (gaussian, bilateral)"))
      .param(real_param("depth_sigma", 0.01, 1e-6, 1e6, "depth units",
                        "Bilateral: a tap whose depth differs by this much weighs exp(-1/2) of a level one"))
      .param(real_param("radius_uv", 0.0, 0.0, 0.05, "shadow-map UV",
                        "When > 0 (a texture covering the shadow map): radius = ceil(radius_uv x "
                        "radius_uv_scale x width), 1..16 texels"))
      .param(real_param("radius_uv_scale", 1.0, 1.0, 2.0, "", "Multiplies radius_uv"))
      .param(real_param("penumbra_height", 0.0, 0.0, 2.0, "of the scene's height along the light",
                        "When > 0 (gaussian, bilateral; a texture covering the shadow map): sigma = the "
                        "standard deviation of the frame light's penumbra across an edge this high above "
                        "its receiver (width / 4; heights as a fraction of the scene's height along the "
                        "light's rays, scene::blocker_height_scale, so a value suits a scene at any scale), "
                        "at most 16/3 texels, radius = ceil(3 sigma); overrides sigma and radius"))
      .build<SeparableFilterPass>();
}

}  // namespace penumbra::passes
