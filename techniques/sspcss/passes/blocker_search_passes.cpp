// Blocker search and penumbra estimate (section 1) in screen space, with the edge-aware filters
// of section 2: separable (rows, then columns + estimate) or one Poisson-disk pass.
#include <vector>

#include "exec/pass_decl_builder.h"
#include "techniques/sspcss/passes/sspcss_pass_common.h"
#include "techniques/sspcss/passes/sspcss_pass_types.h"

namespace penumbra::sspcss {
namespace {

using graph::Format;

// The G-buffer centre and the light, which every search pass reads.
exec::PassDeclBuilder search_pass(const char* name, const char* description) {
  exec::PassDeclBuilder b(name);
  b.describe(description)
      .sampled("depth", {Format::R32F})
      .sampled("normal", {Format::RG16})
      .imported("light", false);
  for (graph::ParamDesc& d : range_params()) b.param(std::move(d));
  for (graph::ParamDesc& d : search_params()) b.param(std::move(d));
  b.param(footprint_param());
  return b;
}

Status set_common(const gl::ShaderProgram& p, exec::PassContext& ctx) {
  set_screen_uniforms(p.program(), ctx.frame());
  set_range_uniforms(p.program(), ctx);
  set_footprint_uniform(p.program(), ctx);
  return set_penumbra_uniforms(p.program(), ctx);
}

class SearchRowsPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/sspcss/shaders/blocker_search_x.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_projected", "projected");
    ctx.bind_image(0, "rows", GL_WRITE_ONLY);
    if (Status s = set_common(p, ctx); !s) return s;
    set_separable_uniforms(p.program(), ctx);
    ctx.dispatch_over(p, ctx.texture("rows"));
    return {};
  }
};

class SearchColumnsPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/sspcss/shaders/blocker_search_y.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_rows", "rows");
    ctx.bind_image(0, "blocker", GL_WRITE_ONLY);
    ctx.bind_image(1, "penumbra", GL_WRITE_ONLY);
    if (Status s = set_common(p, ctx); !s) return s;
    set_separable_uniforms(p.program(), ctx);
    set_fixed_radius_uniform(p.program(), ctx);
    ctx.dispatch_over(p, ctx.texture("blocker"));
    return {};
  }
};

class SearchPoissonPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/sspcss/shaders/blocker_search_poisson.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_projected", "projected");
    ctx.bind_image(0, "blocker", GL_WRITE_ONLY);
    ctx.bind_image(1, "penumbra", GL_WRITE_ONLY);
    if (Status s = set_common(p, ctx); !s) return s;
    set_poisson_uniforms(p.program(), ctx, disk_);
    set_fixed_radius_uniform(p.program(), ctx);
    ctx.dispatch_over(p, ctx.texture("blocker"));
    return {};
  }

 private:
  std::vector<glm::vec2> disk_;
};

}  // namespace

exec::PassType blocker_search_x_pass_type() {
  return search_pass("sspcss_blocker_search_x",
                     "SSPCSS blocker search along rows: mean blocker distance and coverage per row (compute)")
      .sampled("projected", {Format::RGBA16F})
      .image_out("rows", {Format::RGBA16F})
      .same_size({"depth", "normal", "projected", "rows"})
      .param(separable_taps_param())
      .build<SearchRowsPass>();
}

exec::PassType blocker_search_y_pass_type() {
  return search_pass("sspcss_blocker_search_y",
                     "SSPCSS blocker search along columns, then the penumbra estimate W_screen (compute)")
      .sampled("rows", {Format::RGBA16F})
      .image_out("blocker", {Format::R32F})
      .image_out("penumbra", {Format::R16F})
      .same_size({"depth", "normal", "rows", "blocker", "penumbra"})
      .param(separable_taps_param())
      .param(fixed_radius_param())
      .build<SearchColumnsPass>();
}

exec::PassType blocker_search_poisson_pass_type() {
  return search_pass("sspcss_blocker_search_poisson",
                     "SSPCSS blocker search over a Poisson disk, then the penumbra estimate W_screen (compute)")
      .sampled("projected", {Format::RGBA16F})
      .image_out("blocker", {Format::R32F})
      .image_out("penumbra", {Format::R16F})
      .same_size({"depth", "normal", "projected", "blocker", "penumbra"})
      .param(poisson_taps_param())
      .param(fixed_radius_param())
      .build<SearchPoissonPass>();
}

}  // namespace penumbra::sspcss
