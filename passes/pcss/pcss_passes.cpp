// The two PCSS passes (shaders: pcss_blocker_search.comp.glsl, pcss_filter.comp.glsl).
#include "passes/pcss/pcss_passes.h"

#include <optional>

#include "passes/common/shadow_uniforms.h"

namespace penumbra::passes {
namespace {

using graph::Access;
using graph::Format;
using graph::ParamDesc;
using graph::ParamType;
using graph::SlotKind;
using graph::Usage;

ParamDesc samples_param(const char* what) {
  ParamDesc d{.name = "samples", .type = ParamType::integer, .default_value = 16, .min = 4, .max = 64};
  d.description = std::string("Vogel-disk taps of the ") + what;
  return d;
}

ParamDesc light_size_scale_param() {
  ParamDesc d{.name = "light_size_scale", .type = ParamType::real, .default_value = 1.0, .min = 0.0, .max = 10.0};
  d.description = "Multiplier on the light's emitter diameter (Light::size)";
  return d;
}

ParamDesc depth_bias_param() {
  ParamDesc d{.name = "depth_bias", .type = ParamType::real, .default_value = 0.0002, .min = 0.0, .max = 0.05};
  d.unit = "window depth";
  d.description = "Constant bias subtracted from the receiver-plane depth of every tap";
  return d;
}

ParamDesc max_uv_param(const char* name, const char* what) {
  ParamDesc d{.name = name, .type = ParamType::real, .default_value = 0.05, .min = 0.0, .max = 1.0};
  d.unit = "shadow-map UV";
  d.description = std::string("Upper bound of the ") + what + " width";
  return d;
}

std::vector<graph::SlotDecl> receiver_slots() {
  return {
      {"position", Access::read, SlotKind::texture, {Format::RGBA32F}, Usage::sampled, true},
      {"normal", Access::read, SlotKind::texture, {Format::RGBA16F, Format::RGBA32F}, Usage::sampled, true},
      {"shadow_map", Access::read, SlotKind::texture, {Format::DEPTH32F}, Usage::sampled, true},
      {"light", Access::read, SlotKind::imported, {}, Usage::imported, false},
  };
}

class BlockerSearchPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "passes/pcss/pcss_blocker_search.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    // Raw depths for textureGather: no comparison (the filter pass uses the compare sampler).
    if (!raw_) raw_.emplace(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp, false);
    ctx.bind_sampled(p, "u_position", "position");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", raw_->id());
    ctx.bind_image(0, "blocker", GL_WRITE_ONLY);
    set_shadow_uniforms(p.program(), ctx.frame());
    const gl::Program& prog = p.program();
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    prog.set("u_samples", ctx.integer("samples"));
    prog.set("u_light_size_scale", ctx.real("light_size_scale"));
    prog.set("u_max_search_uv", ctx.real("max_search_uv"));
    gl::Texture& out = ctx.texture("blocker");
    ctx.dispatch_over(p, out.width(), out.height());
    return {};
  }

 private:
  std::optional<gl::Sampler> raw_;
};

class FilterPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "passes/pcss/pcss_filter.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    if (!compare_) compare_.emplace(gl::Sampler::Filter::linear, gl::Sampler::Wrap::clamp, true);
    ctx.bind_sampled(p, "u_position", "position");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_blocker", "blocker");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", compare_->id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    set_shadow_uniforms(p.program(), ctx.frame());
    const gl::Program& prog = p.program();
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    prog.set("u_samples", ctx.integer("samples"));
    prog.set("u_light_size_scale", ctx.real("light_size_scale"));
    prog.set("u_max_filter_uv", ctx.real("max_filter_uv"));
    gl::Texture& mask = ctx.texture("mask");
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }

 private:
  std::optional<gl::Sampler> compare_;
};

}  // namespace

exec::PassType pcss_blocker_search_pass_type() {
  graph::PassTypeDecl d;
  d.name = "pcss_blocker_search";
  d.description = "PCSS blocker search: mean blocker distance (world units, 0 = none) (compute)";
  d.slots = receiver_slots();
  d.slots.push_back({"blocker", Access::write, SlotKind::texture, {Format::R32F}, Usage::image_store, true});
  d.same_size_groups = {{"position", "normal", "blocker"}};
  d.params = {samples_param("blocker search"), light_size_scale_param(), depth_bias_param(),
              max_uv_param("max_search_uv", "blocker search region")};
  return {d, [] { return std::make_unique<BlockerSearchPass>(); }};
}

exec::PassType pcss_filter_pass_type() {
  graph::PassTypeDecl d;
  d.name = "pcss_filter";
  d.description = "PCSS penumbra estimate (Fernando 2005 eq. 1) and PCF of that width (compute)";
  d.slots = receiver_slots();
  d.slots.push_back({"blocker", Access::read, SlotKind::texture, {Format::R32F}, Usage::sampled, true});
  d.slots.push_back({"mask", Access::write, SlotKind::texture, {Format::R16F}, Usage::image_store, true});
  d.same_size_groups = {{"position", "normal", "blocker", "mask"}};
  d.params = {samples_param("filter"), light_size_scale_param(), depth_bias_param(),
              max_uv_param("max_filter_uv", "filter kernel")};
  return {d, [] { return std::make_unique<FilterPass>(); }};
}

}  // namespace penumbra::passes
