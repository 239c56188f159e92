// techniques/_template is not a built-in, so nothing else compiles it: this test builds its
// pass type, registers the technique beside the built-ins and renders it, so the copy-me
// folder always matches the real pass library and graph format. As a shared-library plugin it
// is tested in tests/plugin.
#include <gtest/gtest.h>

#include "baseline_frame.h"
#include "test_support/gl_context.h"
#include "techniques/_template/template_technique.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {
namespace {

TEST(TemplateTechnique, CompilesAgainstThePassLibraryAndRenders) {
  gl_context();
  technique::TechniqueRegistry registry;
  register_builtin_techniques(registry);
  template_technique::register_technique(registry);
  exec::PassLibrary library = make_pass_library(registry);
  technique::TechniqueSession session(registry, library);
  session.set_scene(builtin_scene("ball"));
  ASSERT_TRUE(session.resize(128, 96));
  ASSERT_TRUE(session.set_shadow_size(1024));
  Status s = session.set_technique("template");
  ASSERT_TRUE(s) << s.error().to_string();
  ASSERT_EQ(session.params().descs().size(), 1u);

  for (double strength : {1.0, 0.5}) {
    ASSERT_TRUE(session.set_param("shadow_strength", strength));
    ASSERT_TRUE(session.render());
    gl::Texture* mask = session.executor().resource("shadow_mask");
    ASSERT_NE(mask, nullptr);
    size_t lit = 0, shadowed = 0;
    for (float v : mask->read()) {
      ASSERT_TRUE(v == 1.0f || std::abs(v - float(1.0 - strength)) < 1e-3f) << v;
      (v == 1.0f ? lit : shadowed)++;
    }
    EXPECT_GT(lit, 0u);
    EXPECT_GT(shadowed, 20u);
  }
  EXPECT_EQ(session.compile_count(), 1) << "a uniform parameter must not recompile";

  // A point light inside the scene: the template's pass keeps set_shadow_uniforms' default
  // (SixFaces::refused), so the frame is a bad-input Error naming the techniques that take it.
  scene::Scene lamp = builtin_scene("ball");
  lamp.light.type = scene::LightType::point;
  lamp.light.position = {0.0f, 1.0f, 1.0f};
  session.set_scene(lamp);
  ASSERT_TRUE(session.set_technique("template"));
  s = session.render();
  ASSERT_FALSE(s);
  const std::string msg = s.error().to_string();
  EXPECT_NE(msg.find("inside the scene bounds"), std::string::npos) << msg;
  EXPECT_NE(msg.find("hard, pcf, pcss, pmchss, mpg, sspcss and esm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("template_mask"), std::string::npos) << "the pass is named: " << msg;
  EXPECT_EQ(s.error().exit_code(), 2);
}

}  // namespace
}  // namespace penumbra::test
