// Shadow filtering (section 1): the hard visibility filtered by an edge-aware kernel of diameter
// W_screen (section 2): separable cross-bilateral Gaussian (rows, then columns) or one
// cross-bilateral Poisson pass.
#include <vector>

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_uniforms.h"
#include "techniques/sspcss/passes/sspcss_pass_common.h"
#include "techniques/sspcss/passes/sspcss_pass_types.h"

namespace penumbra::sspcss {
namespace {

using graph::Format;

// The inputs every filter pass reads: the centre's position and normal (range term, footprint),
// the light (footprint), the projected shadow map (hard visibility, view depth) and W_screen.
exec::PassDeclBuilder filter_pass(const char* name, const char* description) {
  exec::PassDeclBuilder b(name);
  b.describe(description)
      .sampled("depth", {Format::R32F})
      .sampled("normal", {Format::RG16})
      .imported("light", false)
      .sampled("projected", {Format::RGBA16F})
      .sampled("penumbra", {Format::R16F});
  for (graph::ParamDesc& d : range_params()) b.param(std::move(d));
  b.param(footprint_param());
  return b;
}

Status bind_common(const gl::ShaderProgram& p, exec::PassContext& ctx) {
  ctx.bind_sampled(p, "u_depth", "depth");
  ctx.bind_sampled(p, "u_normal", "normal");
  ctx.bind_sampled(p, "u_projected", "projected");
  ctx.bind_sampled(p, "u_penumbra", "penumbra");
  set_screen_uniforms(p.program(), ctx.frame());
  set_range_uniforms(p.program(), ctx);
  set_footprint_uniform(p.program(), ctx);
  return passes::set_shadow_uniforms(p.program(), ctx.frame(), passes::SixFaces::read);
}

class FilterRowsPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/sspcss/shaders/shadow_filter_x.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    if (Status s = bind_common(p, ctx); !s) return s;
    ctx.bind_image(0, "rows", GL_WRITE_ONLY);
    set_separable_uniforms(p.program(), ctx);
    ctx.dispatch_over(p, ctx.texture("rows"));
    return {};
  }
};

class FilterColumnsPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/sspcss/shaders/shadow_filter_y.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    if (Status s = bind_common(p, ctx); !s) return s;
    ctx.bind_sampled(p, "u_rows", "rows");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    set_separable_uniforms(p.program(), ctx);
    ctx.dispatch_over(p, ctx.texture("mask"));
    return {};
  }
};

class FilterPoissonPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/sspcss/shaders/shadow_filter_poisson.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    if (Status s = bind_common(p, ctx); !s) return s;
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    set_poisson_uniforms(p.program(), ctx, disk_);
    ctx.dispatch_over(p, ctx.texture("mask"));
    return {};
  }

 private:
  std::vector<glm::vec2> disk_;
};

}  // namespace

exec::PassType filter_x_pass_type() {
  return filter_pass("sspcss_filter_x", "SSPCSS cross-bilateral Gaussian of the hard shadow along rows (compute)")
      .image_out("rows", {Format::RGBA16F})
      .same_size({"depth", "normal", "projected", "penumbra", "rows"})
      .param(separable_taps_param())
      .build<FilterRowsPass>();
}

exec::PassType filter_y_pass_type() {
  return filter_pass("sspcss_filter_y",
                     "SSPCSS cross-bilateral Gaussian along columns: the shadow mask (compute)")
      .sampled("rows", {Format::RGBA16F})
      .image_out("mask", {Format::R16F})
      .same_size({"depth", "normal", "projected", "penumbra", "rows", "mask"})
      .param(separable_taps_param())
      .build<FilterColumnsPass>();
}

exec::PassType filter_poisson_pass_type() {
  return filter_pass("sspcss_filter_poisson",
                     "SSPCSS cross-bilateral Poisson filter of the hard shadow: the shadow mask (compute)")
      .image_out("mask", {Format::R16F})
      .same_size({"depth", "normal", "projected", "penumbra", "mask"})
      .param(poisson_taps_param())
      .build<FilterPoissonPass>();
}

}  // namespace penumbra::sspcss
