#include "pmchss_fixture.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <limits>

#include "metrics/heat_map.h"
#include "techniques/builtin_techniques.h"
#include "test_support/gl_context.h"

namespace penumbra::test {

struct PmchssRig::State {
  plugin::TechniqueRegistry registry;
  exec::PassLibrary library;
};

PmchssRig::PmchssRig(int width, int height, int shadow_size) : state_(std::make_unique<State>()) {
  gl_context();
  register_builtin_techniques(state_->registry);
  state_->library = make_pass_library(state_->registry);
  session_ = std::make_unique<plugin::TechniqueSession>(state_->registry, state_->library);
  Status s = session_->resize(width, height);
  EXPECT_TRUE(s) << s.error().to_string();
  s = session_->set_shadow_size(shadow_size);
  EXPECT_TRUE(s) << s.error().to_string();
}

PmchssRig::~PmchssRig() = default;

void PmchssRig::set_scene(const scene::Scene& scene) {
  session_->set_scene(scene);
  if (session_->technique().empty()) {
    Status s = session_->set_technique("pmchss");
    ASSERT_TRUE(s) << s.error().to_string() << "\n" << s.error().details;
  }
}

void PmchssRig::set(const std::vector<std::string>& assignments) {
  for (const std::string& a : assignments) {
    Status s = session_->set_param(a);
    ASSERT_TRUE(s) << a << ": " << s.error().to_string() << "\n" << s.error().details;
  }
}

void PmchssRig::render() {
  Status s = session_->render();
  ASSERT_TRUE(s) << s.error().to_string();
}

metrics::MaskImage PmchssRig::read(const std::string& resource) {
  gl::Texture* t = session_->executor().resource(resource);
  if (!t) return {};
  std::vector<float> texels = t->read();
  int channels = t->info().channels;
  metrics::MaskImage m(t->width(), t->height());
  for (int y = 0; y < t->height(); ++y)
    for (int x = 0; x < t->width(); ++x)
      m.at(x, t->height() - 1 - y) = texels[(static_cast<size_t>(y) * t->width() + x) * channels];
  return m;
}

void PmchssRig::gbuffer(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                        metrics::CoverageMask& coverage) {
  gl::Texture* pos = session_->executor().resource("gbuffer_position");
  gl::Texture* nrm = session_->executor().resource("gbuffer_normal");
  ASSERT_TRUE(pos && nrm);
  std::vector<float> p = pos->read(), n = nrm->read();
  int w = pos->width(), h = pos->height();
  positions.assign(static_cast<size_t>(w) * h, glm::vec3(0));
  normals.assign(positions.size(), glm::vec3(0, 1, 0));
  coverage.assign(positions.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      size_t src = static_cast<size_t>(y) * w + x;
      size_t dst = static_cast<size_t>(h - 1 - y) * w + x;
      bool hit = p[src * 4 + 3] > 0.0f;
      coverage[dst] = hit ? 1 : 0;
      positions[dst] = hit ? glm::vec3(p[src * 4], p[src * 4 + 1], p[src * 4 + 2])
                           : glm::vec3(std::numeric_limits<float>::quiet_NaN());
      normals[dst] = glm::vec3(n[src * 4], n[src * 4 + 1], n[src * 4 + 2]);
    }
}

metrics::MaskImage PmchssRig::world_y() {
  gl::Texture* pos = session_->executor().resource("gbuffer_position");
  std::vector<float> p = pos->read();
  metrics::MaskImage m(pos->width(), pos->height());
  for (int y = 0; y < pos->height(); ++y)
    for (int x = 0; x < pos->width(); ++x) {
      size_t src = (static_cast<size_t>(y) * pos->width() + x) * 4;
      m.at(x, pos->height() - 1 - y) =
          p[src + 3] > 0.0f ? p[src + 1] : std::numeric_limits<float>::quiet_NaN();
    }
  return m;
}

metrics::CoverageMask PmchssRig::coverage() {
  gl::Texture* pos = session_->executor().resource("gbuffer_position");
  std::vector<float> p = pos->read();
  metrics::CoverageMask c(static_cast<size_t>(pos->width()) * pos->height(), 0);
  for (int y = 0; y < pos->height(); ++y)
    for (int x = 0; x < pos->width(); ++x)
      c[static_cast<size_t>(pos->height() - 1 - y) * pos->width() + x] =
          p[(static_cast<size_t>(y) * pos->width() + x) * 4 + 3] > 0.0f ? 1 : 0;
  return c;
}

void save_for_inspection(const std::string& name, const metrics::MaskImage& image) {
  const char* dir = std::getenv("PMCHSS_TEST_IMAGES");
  if (!dir || image.width == 0) return;
  std::filesystem::create_directories(dir);
  (void)metrics::write_png(std::string(dir) + "/" + name + ".png", image);
}

}  // namespace penumbra::test
