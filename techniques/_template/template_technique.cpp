// The template technique: one compute pass type and the technique's registration.
// See README.md for how to make it a built-in or a shared-library plugin.
#include "techniques/_template/template_technique.h"

#include "passes/common/shadow_uniforms.h"

namespace penumbra::template_technique {
namespace {

using graph::Access;
using graph::Format;
using graph::SlotKind;
using graph::Usage;

class TemplateMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    // Shader paths are repository-relative; the program is cached and hot-reloaded.
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/_template/template_mask.comp.glsl"});
    if (!p.valid()) return *p.last_error();       // compile error: file and line, shown in the UI
    ctx.bind_sampled(p, "u_position", "position");  // slot -> texture unit -> uniform
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);       // layout(binding = 0) in the shader
    passes::set_shadow_uniforms(p.program(), ctx.frame());  // shadow_common.glsl's uniforms
    p.program().set("u_strength", ctx.real("strength"));    // live value of "$shadow_strength"
    gl::Texture& mask = ctx.texture("mask");
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }
};

}  // namespace

exec::PassType template_mask_pass_type() {
  graph::PassTypeDecl d;
  d.name = "template_mask";
  d.description = "Template: hard shadow test scaled by a strength (compute)";
  d.slots = {
      {"position", Access::read, SlotKind::texture, {Format::RGBA32F}, Usage::sampled, true},
      {"shadow_map", Access::read, SlotKind::texture, {Format::DEPTH32F}, Usage::sampled, true},
      {"mask", Access::write, SlotKind::texture, {Format::R16F}, Usage::image_store, true},
  };
  d.same_size_groups = {{"position", "mask"}};
  graph::ParamDesc strength{.name = "strength", .type = graph::ParamType::real, .default_value = 1.0,
                            .min = 0.0, .max = 1.0};
  strength.description = "0 = no shadow, 1 = full hard shadow";
  d.params = {strength};
  return {d, [] { return std::make_unique<TemplateMaskPass>(); }};
}

void register_technique(plugin::TechniqueRegistry& registry) {
  registry.add({.name = "template",
                .description = "Copy-me technique: hard shadow lightened by shadow_strength",
                .graph_file = "techniques/_template/template.json",
                .register_passes = [](exec::PassLibrary& library) { library.add(template_mask_pass_type()); }});
}

}  // namespace penumbra::template_technique
