// light_view_pass_type() as a plugin author uses it: a fragment shader of the author's writes a
// colour target beside the depth map. Where a caster is drawn the target holds that fragment's
// window depth, equal to the depth map's (biases 0); elsewhere the declared clear value; an
// alpha-masked caster's holes are holes in both; a target of the wrong size is refused.
#include <gtest/gtest.h>

#include "passes/shadow_map/light_view_pass.h"
#include "scene/mesh_builder.h"
#include "techniques/builtin_techniques.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {
namespace {

void register_probe(technique::TechniqueRegistry& registry) {
  register_builtin_techniques(registry);
  registry.add({.name = "light_view_probe",
                .graph_file = "tests/passes/light_view_probe.json",
                .register_passes = [](exec::PassLibrary& library) {
                  library.add(passes::light_view_pass_type(
                      {.type_name = "light_view_probe",
                       .description = "Test: window depth and coverage into a colour target (raster)",
                       .fragment_shader = "tests/passes/shaders/light_view_probe.frag.glsl",
                       .colour_targets = {{.slot = "probe", .formats = {graph::Format::RGBA32F},
                                           .clear = glm::vec4(1.0f, -1.0f, 0.0f, 0.0f)}}}));
                }});
}

constexpr int kShadow = 128;

struct LightView {
  metrics::MaskImage depth, probe_depth, covered;
};

LightView render(const scene::Scene& s) {
  TechniqueRig rig({.width = 64, .height = 48, .shadow_size = kShadow, .technique = "light_view_probe",
                    .techniques = register_probe});
  rig.set_scene(s);
  rig.render();
  return {rig.read("shadow_map"), rig.read("probe", 0), rig.read("probe", 1)};
}

TEST(LightViewPass, TheAuthorsTargetHoldsWhatTheDepthMapHoldsAndTheClearElsewhere) {
  const LightView v = render(builtin_scene("ball"));
  ASSERT_EQ(v.depth.pixels.size(), static_cast<size_t>(kShadow) * kShadow);
  ASSERT_EQ(v.probe_depth.pixels.size(), v.depth.pixels.size());
  int covered = 0, wrong = 0;
  for (size_t i = 0; i < v.depth.pixels.size(); ++i) {
    if (v.covered.pixels[i] == 1.0f) {
      ++covered;
      wrong += std::abs(v.probe_depth.pixels[i] - v.depth.pixels[i]) > 1e-6f;
    } else {
      wrong += v.covered.pixels[i] != -1.0f || v.probe_depth.pixels[i] != 1.0f || v.depth.pixels[i] != 1.0f;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(covered, kShadow * kShadow / 4) << "the ground covers a good part of the map";
  EXPECT_LT(covered, kShadow * kShadow) << "and not all of it";
}

// The ball scene with a quad 0.3 m above the ground over all of it, its texture's alpha `alpha`.
scene::Scene ball_under_quad(uint8_t alpha) {
  scene::Scene s = builtin_scene("ball");
  s.images.push_back({"quad", 1, 1, {255, 255, 255, alpha}});
  s.materials.push_back({.base_color_texture = static_cast<int>(s.images.size() - 1),
                         .alpha_mode = scene::AlphaMode::mask, .alpha_cutoff = 0.5f});
  scene::Mesh quad;
  scene::build::add_ground(quad, {0.0f, 0.3f, 0.0f}, 40.0f, 40.0f);
  quad.material = static_cast<uint32_t>(s.materials.size() - 1);
  s.meshes.push_back(quad);
  s.instances.push_back({static_cast<uint32_t>(s.meshes.size() - 1), glm::mat4(1.0f)});
  return s;  // bounds kept: the shadow frustum is the plain scene's
}

TEST(LightViewPass, AnAlphaMaskedCastersHolesAreHolesInTheAuthorsTarget) {
  const LightView plain = render(builtin_scene("ball"));
  const LightView hole = render(ball_under_quad(0));
  EXPECT_EQ(hole.covered.pixels, plain.covered.pixels);
  EXPECT_EQ(hole.probe_depth.pixels, plain.probe_depth.pixels);
  const LightView opaque = render(ball_under_quad(255));  // the quad is in the light's view
  EXPECT_NE(opaque.probe_depth.pixels, plain.probe_depth.pixels);
}

}  // namespace
}  // namespace penumbra::test
