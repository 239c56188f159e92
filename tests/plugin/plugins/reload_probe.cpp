// The sandbox reload tests' plugin, built twice (RELOAD_PROBE_BUILD 1 and 2) into two plugin
// directories: technique "reload_probe" fills shadow_mask with `level` times a factor of the
// build (1 in build 1, 0.5 in build 2), so a test sees which build runs; each build's graph has
// a parameter the other lacks (reload_probe/build1.json, build2.json).
#include "exec/pass_decl_builder.h"
#include "plugin/plugin_api.h"

#ifndef RELOAD_PROBE_BUILD
#error "define RELOAD_PROBE_BUILD (1 or 2)"
#endif

namespace {

constexpr float kFactor = RELOAD_PROBE_BUILD == 1 ? 1.0f : 0.5f;

class FillPass final : public penumbra::exec::PassImpl {
 public:
  penumbra::Status execute(penumbra::exec::PassContext& ctx) override {
    const float value = static_cast<float>(ctx.real("level")) * kFactor;
    glClearTexImage(ctx.texture("mask").id(), 0, GL_RED, GL_FLOAT, &value);
    return {};
  }
};

void register_technique(penumbra::technique::TechniqueRegistry& registry) {
  registry.add({.name = "reload_probe",
                .graph_file = RELOAD_PROBE_BUILD == 1 ? "reload_probe/build1.json" : "reload_probe/build2.json",
                .register_passes = [](penumbra::exec::PassLibrary& library) {
                  library.add(penumbra::exec::PassDeclBuilder("reload_probe_fill")
                                  .describe("Test: shadow_mask = level * the build's factor")
                                  .image_out("mask", {penumbra::graph::Format::R16F})
                                  .real("level", 0.5, 0.0, 1.0, "", "mask value before the build's factor")
                                  .integer("marker", 3, 0, 10, "", "read by nothing: a parameter one build's graph exposes")
                                  .build<FillPass>());
                }});
}

}  // namespace

PENUMBRA_PLUGIN(register_technique)
