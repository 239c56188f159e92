// The template technique: one compute pass type and the technique's registration.
// See README.md for how to make it a built-in or a shared-library plugin.
#include "techniques/_template/template_technique.h"

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_uniforms.h"

namespace penumbra::template_technique {
namespace {

using graph::Format;

class TemplateMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    // Shader paths are repository-relative; the program is cached and hot-reloaded.
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/_template/template_mask.comp.glsl"});
    if (!p.valid()) return *p.last_error();       // compile error: file and line, shown in the UI
    ctx.bind_sampled(p, "u_depth", "depth");  // slot -> texture unit -> uniform
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);       // layout(binding = 0) in the shader
    if (Status s = passes::set_shadow_uniforms(p.program(), ctx.frame()); !s) return s;  // shadow_common.glsl's uniforms
    p.program().set("u_strength", ctx.real("strength"));    // live value of "$shadow_strength"
    ctx.dispatch_over(p, ctx.texture("mask"));     // one thread per mask texel
    return {};
  }
};

}  // namespace

exec::PassType template_mask_pass_type() {
  // Slots and parameters, declared once; the compiler validates graphs against this and plans
  // the barriers from each slot's usage (image_out then sampled = a texture-fetch barrier).
  return exec::PassDeclBuilder("template_mask")
      .describe("Template: hard shadow test scaled by a strength (compute)")
      .sampled("depth", {Format::R32F})
      .sampled("shadow_map", {Format::DEPTH32F})
      .image_out("mask", {Format::R16F})
      .same_size({"depth", "mask"})
      .real("strength", 1.0, 0.0, 1.0, "", "0 = no shadow, 1 = full hard shadow (mask = 1 - strength * occluded)")
      .build<TemplateMaskPass>();
}

void register_technique(technique::TechniqueRegistry& registry) {
  registry.add({.name = "template",
                .graph_file = "techniques/_template/template.json",
                .register_passes = [](exec::PassLibrary& library) { library.add(template_mask_pass_type()); }});
}

}  // namespace penumbra::template_technique
