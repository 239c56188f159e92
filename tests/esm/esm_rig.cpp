#include "esm_rig.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <limits>

#include "metrics/heat_map.h"
#include "raytraced_reference.h"
#include "test_support/gl_context.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {

struct TechniqueRig::State {
  plugin::TechniqueRegistry registry;
  exec::PassLibrary library;
};

TechniqueRig::TechniqueRig(int width, int height, int shadow_size) : state_(std::make_unique<State>()) {
  gl_context();
  register_builtin_techniques(state_->registry);
  state_->library = make_pass_library(state_->registry);
  session_ = std::make_unique<plugin::TechniqueSession>(state_->registry, state_->library);
  session_->compile_options().keep_alive = {"gbuffer_position", "gbuffer_normal"};
  Status s = session_->resize(width, height);
  EXPECT_TRUE(s) << s.error().to_string();
  set_shadow_size(shadow_size);
}

TechniqueRig::~TechniqueRig() = default;

void TechniqueRig::set_scene(const scene::Scene& scene) { session_->set_scene(scene); }

void TechniqueRig::use(const std::string& technique) {
  Status s = session_->set_technique(technique);
  ASSERT_TRUE(s) << s.error().to_string() << "\n" << s.error().details;
}

void TechniqueRig::set(const std::vector<std::string>& assignments) {
  for (const std::string& a : assignments) {
    Status s = session_->set_param(a);
    ASSERT_TRUE(s) << a << ": " << s.error().to_string() << "\n" << s.error().details;
  }
}

void TechniqueRig::set_shadow_size(int texels) {
  Status s = session_->set_shadow_size(texels);
  ASSERT_TRUE(s) << s.error().to_string();
}

void TechniqueRig::render() {
  Status s = session_->render();
  ASSERT_TRUE(s) << s.error().to_string();
}

metrics::MaskImage TechniqueRig::read(const std::string& resource, int channel) {
  gl::Texture* t = session_->executor().resource(resource);
  if (!t) return {};
  std::vector<float> texels = t->read();
  const int channels = t->info().channels;
  channel = std::min(channel, channels - 1);
  metrics::MaskImage m(t->width(), t->height());
  for (int y = 0; y < t->height(); ++y)
    for (int x = 0; x < t->width(); ++x)
      m.at(x, t->height() - 1 - y) = texels[(static_cast<size_t>(y) * t->width() + x) * channels + channel];
  return m;
}

metrics::CoverageMask TechniqueRig::coverage() {
  metrics::MaskImage w = read("gbuffer_position", 3);
  metrics::CoverageMask c(w.pixels.size(), 0);
  for (size_t i = 0; i < c.size(); ++i) c[i] = w.pixels[i] > 0.0f ? 1 : 0;
  return c;
}

void TechniqueRig::gbuffer(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                           metrics::CoverageMask& coverage) {
  gl::Texture* pos = session_->executor().resource("gbuffer_position");
  gl::Texture* nrm = session_->executor().resource("gbuffer_normal");
  ASSERT_TRUE(pos && nrm);
  std::vector<float> p = pos->read(), n = nrm->read();
  const int w = pos->width(), h = pos->height();
  positions.assign(static_cast<size_t>(w) * h, glm::vec3(0));
  normals.assign(positions.size(), glm::vec3(0, 1, 0));
  coverage.assign(positions.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t src = static_cast<size_t>(y) * w + x;
      const size_t dst = static_cast<size_t>(h - 1 - y) * w + x;
      const bool hit = p[src * 4 + 3] > 0.0f;
      coverage[dst] = hit ? 1 : 0;
      positions[dst] = hit ? glm::vec3(p[src * 4], p[src * 4 + 1], p[src * 4 + 2])
                           : glm::vec3(std::numeric_limits<float>::quiet_NaN());
      normals[dst] = glm::vec3(n[src * 4], n[src * 4 + 1], n[src * 4 + 2]);
    }
}

metrics::MaskImage exact_hard_reference(TechniqueRig& rig, const scene::Scene& scene, int pixel_samples) {
  std::vector<glm::vec3> positions, normals;
  metrics::CoverageMask coverage;
  rig.gbuffer(positions, normals, coverage);
  Result<reference::RayScene> rs = reference::RayScene::build(scene);
  EXPECT_TRUE(rs);
  if (!rs) return {};
  scene::Light light = rig.session().light();
  light.size = 0.0f;
  reference::TraceOptions options{.samples = 1};
  options.pixel_samples = pixel_samples;
  options.camera = rig.session().camera();
  const plugin::TechniqueSession& s = rig.session();
  return reference::trace_visibility(*rs, light, positions, normals, s.settings().screen_w, s.settings().screen_h,
                                     options, coverage);
}

void save_for_inspection(const std::string& name, const metrics::MaskImage& image) {
  const char* dir = std::getenv("ESM_TEST_IMAGES");
  if (!dir || image.width == 0) return;
  std::filesystem::create_directories(dir);
  (void)metrics::write_png(std::string(dir) + "/" + name + ".png", image);
}

}  // namespace penumbra::test
