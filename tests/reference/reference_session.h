#pragma once
// A TechniqueSession on a built-in scene at a small size, rendering the `reference` technique,
// with the mask and coverage read back as metrics images.
#include <gtest/gtest.h>

#include <memory>

#include "cli/eval_capture.h"
#include "plugin/technique_session.h"
#include "scene/builtin_scenes.h"
#include "test_support/gl_context.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {

struct ReferenceSession {
  plugin::TechniqueRegistry registry;
  exec::PassLibrary library;
  std::unique_ptr<plugin::TechniqueSession> session;

  explicit ReferenceSession(const std::string& scene_name, int size = 128) {
    gl_context();
    register_builtin_techniques(registry);
    library = make_pass_library(registry);
    session = std::make_unique<plugin::TechniqueSession>(registry, library);
    auto s = scene::make_builtin_scene(scene_name);
    EXPECT_TRUE(s) << (s ? "" : s.error().to_string());
    session->set_scene(*s);
    session->compile_options().keep_alive.push_back("gbuffer_position");
    EXPECT_TRUE(session->resize(size, size));
    Status t = session->set_technique("reference");
    EXPECT_TRUE(t) << (t ? "" : t.error().to_string());
  }

  void set(const std::string& kv) {
    Status s = session->set_param(kv);
    EXPECT_TRUE(s) << kv << ": " << (s ? "" : s.error().to_string());
  }
  void render(int frames = 1) {
    for (int i = 0; i < frames; ++i) {
      Status s = session->render();
      ASSERT_TRUE(s) << s.error().to_string();
    }
  }
  metrics::MaskImage mask() { return cli::read_mask_image(*session->executor().resource("shadow_mask")); }
  metrics::CoverageMask coverage() {
    return cli::read_coverage(*session->executor().resource("gbuffer_position"));
  }
};

}  // namespace penumbra::test
