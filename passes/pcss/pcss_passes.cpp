// The two PCSS passes (shaders: pcss_blocker_search.comp.glsl, pcss_filter.comp.glsl).
#include "passes/pcss/pcss_passes.h"

#include <optional>

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_receiver_decl.h"
#include "passes/common/shadow_uniforms.h"
#include "passes/sampling/rotation_noise.h"
#include "passes/shadow_tiles/tiled_dispatch.h"

namespace penumbra::passes {
namespace {

using graph::Format;
using graph::ParamDesc;

graph::ParamDesc samples_param(const char* description) {
  return graph::int_param("samples", 16, 4, 64, "", description);
}

graph::ParamDesc light_size_scale_param() {
  return graph::real_param("light_size_scale", 1.0, 0.0, 10.0, "",
                           "Multiplier on the light's emitter diameter (Light::size)");
}

graph::ParamDesc depth_bias_param() {
  return graph::real_param("depth_bias", 0.0002, 0.0, 0.05, "window depth",
                           "Constant bias subtracted from the receiver-plane depth of every tap");
}

graph::ParamDesc max_uv_param(const char* name, const char* what) {
  return graph::real_param(name, 0.05, 0.0, 1.0, "shadow-map UV", std::string("Upper bound of the ") + what + " width");
}


class BlockerSearchPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    // No blocker (0) outside the penumbra tiles: the filter never reads them there.
    if (Status filled = fill_constant_tiles(ctx, {{"blocker", glm::vec4(0.0f), glm::vec4(0.0f)}}); !filled)
      return filled;
    gl::ShaderProgram& p =
        ctx.program({.compute = "passes/pcss/pcss_blocker_search.comp.glsl", .defines = tile_defines(ctx)});
    if (!p.valid()) return *p.last_error();
    // Raw depths for textureGather: no comparison (the filter pass uses the compare sampler).
    if (!raw_) raw_.emplace(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp, false);
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", raw_->id());
    ctx.bind_image(0, "blocker", GL_WRITE_ONLY);
    if (Status s = set_shadow_uniforms(p.program(), ctx.frame(), SixFaces::read); !s) return s;
    const gl::Program& prog = p.program();
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    prog.set("u_samples", ctx.integer("samples"));
    prog.set("u_light_size_scale", ctx.real("light_size_scale"));
    prog.set("u_max_search_uv", ctx.real("max_search_uv"));
    set_rotation_noise(prog, ctx);
    gl::Texture& out = ctx.texture("blocker");
    dispatch_screen(ctx, p, out.width(), out.height());
    return {};
  }

 private:
  std::optional<gl::Sampler> raw_;
};

class FilterPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    if (Status filled = fill_constant_tiles(ctx, {{"mask", glm::vec4(1.0f), glm::vec4(0.0f)}}); !filled) return filled;
    gl::ShaderProgram& p = ctx.program({.compute = "passes/pcss/pcss_filter.comp.glsl", .defines = tile_defines(ctx)});
    if (!p.valid()) return *p.last_error();
    if (!compare_) compare_.emplace(gl::Sampler::Filter::linear, gl::Sampler::Wrap::clamp, true);
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_blocker", "blocker");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", compare_->id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    if (Status s = set_shadow_uniforms(p.program(), ctx.frame(), SixFaces::read); !s) return s;
    const gl::Program& prog = p.program();
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    prog.set("u_samples", ctx.integer("samples"));
    prog.set("u_light_size_scale", ctx.real("light_size_scale"));
    prog.set("u_max_filter_uv", ctx.real("max_filter_uv"));
    set_rotation_noise(prog, ctx);
    gl::Texture& mask = ctx.texture("mask");
    dispatch_screen(ctx, p, mask.width(), mask.height());
    return {};
  }

 private:
  std::optional<gl::Sampler> compare_;
};

}  // namespace

exec::PassType pcss_blocker_search_pass_type() {
  exec::PassDeclBuilder b = shadow_receiver_pass(
      "pcss_blocker_search", "PCSS blocker search: mean blocker distance (world units, 0 = none) (compute)");
  add_tile_slots(b);
  return b.image_out("blocker", {Format::R32F})
      .same_size({"depth", "normal", "blocker"})
      .param(samples_param("Blocker-search taps (each a textureGather of 4 texels), Vogel disk rotated per receiver"))
      .param(light_size_scale_param())
      .param(depth_bias_param())
      .param(max_uv_param("max_search_uv", "blocker search region"))
      .param(rotation_noise_param())
      .build<BlockerSearchPass>();
}

exec::PassType pcss_filter_pass_type() {
  exec::PassDeclBuilder b = shadow_receiver_pass(
      "pcss_filter", "PCSS penumbra estimate (Fernando 2005 eq. 1) and PCF of that width (compute)");
  add_tile_slots(b);
  return b.sampled("blocker", {Format::R32F})
      .image_out("mask", {Format::R16F})
      .same_size({"depth", "normal", "blocker", "mask"})
      .param(samples_param("PCF taps (bilinear hardware comparisons), Vogel disk rotated per receiver"))
      .param(light_size_scale_param())
      .param(depth_bias_param())
      .param(max_uv_param("max_filter_uv", "filter kernel"))
      .param(rotation_noise_param())
      .build<FilterPass>();
}

}  // namespace penumbra::passes
