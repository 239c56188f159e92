#include "mpg_rig.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <limits>

#include "metrics/heat_map.h"
#include "test_support/gl_context.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {

struct MpgRig::State {
  plugin::TechniqueRegistry registry;
  exec::PassLibrary library;
};

MpgRig::MpgRig(int width, int height, int shadow_size) : state_(std::make_unique<State>()) {
  gl_context();
  register_builtin_techniques(state_->registry);
  state_->library = make_pass_library(state_->registry);
  session_ = std::make_unique<plugin::TechniqueSession>(state_->registry, state_->library);
  Status s = session_->resize(width, height);
  EXPECT_TRUE(s) << s.error().to_string();
  s = session_->set_shadow_size(shadow_size);
  EXPECT_TRUE(s) << s.error().to_string();
}

MpgRig::~MpgRig() = default;

void MpgRig::set_scene(const scene::Scene& scene) {
  session_->set_scene(scene);
  if (session_->technique().empty()) {
    Status s = session_->set_technique("mpg");
    ASSERT_TRUE(s) << s.error().to_string() << "\n" << s.error().details;
  }
}

void MpgRig::set(const std::vector<std::string>& assignments) {
  for (const std::string& a : assignments) {
    Status s = session_->set_param(a);
    ASSERT_TRUE(s) << a << ": " << s.error().to_string() << "\n" << s.error().details;
  }
}

void MpgRig::render() {
  Status s = session_->render();
  ASSERT_TRUE(s) << s.error().to_string();
}

metrics::MaskImage MpgRig::read(const std::string& resource, int channel) {
  gl::Texture* t = session_->executor().resource(resource);
  if (!t) return {};
  std::vector<float> texels = t->read();
  const int channels = t->info().channels;
  metrics::MaskImage m(t->width(), t->height());
  for (int y = 0; y < t->height(); ++y)
    for (int x = 0; x < t->width(); ++x)
      m.at(x, t->height() - 1 - y) = texels[(static_cast<size_t>(y) * t->width() + x) * channels + channel];
  return m;
}

metrics::RgbaImage MpgRig::read_rgba(const std::string& resource) {
  metrics::RgbaImage out;
  gl::Texture* t = session_->executor().resource(resource);
  if (!t || t->info().channels != 4) return out;
  std::vector<float> texels = t->read();
  out.width = t->width();
  out.height = t->height();
  out.pixels.resize(static_cast<size_t>(out.width) * out.height * 4);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width * 4; ++x)
      out.pixels[static_cast<size_t>(out.height - 1 - y) * out.width * 4 + x] =
          static_cast<uint8_t>(std::clamp(texels[static_cast<size_t>(y) * out.width * 4 + x], 0.0f, 1.0f) * 255.0f + 0.5f);
  return out;
}

void MpgRig::gbuffer(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
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
      const size_t src = static_cast<size_t>(y) * w + x, dst = static_cast<size_t>(h - 1 - y) * w + x;
      const bool hit = p[src * 4 + 3] > 0.0f;
      coverage[dst] = hit ? 1 : 0;
      positions[dst] = hit ? glm::vec3(p[src * 4], p[src * 4 + 1], p[src * 4 + 2])
                           : glm::vec3(std::numeric_limits<float>::quiet_NaN());
      normals[dst] = glm::vec3(n[src * 4], n[src * 4 + 1], n[src * 4 + 2]);
    }
}

metrics::MaskImage MpgRig::world_y() {
  metrics::MaskImage y = read("gbuffer_position", 1), w = read("gbuffer_position", 3);
  for (size_t i = 0; i < y.pixels.size(); ++i)
    if (w.pixels[i] <= 0.0f) y.pixels[i] = std::numeric_limits<float>::quiet_NaN();
  return y;
}

metrics::CoverageMask MpgRig::coverage() {
  metrics::MaskImage w = read("gbuffer_position", 3);
  metrics::CoverageMask c(w.pixels.size(), 0);
  for (size_t i = 0; i < c.size(); ++i) c[i] = w.pixels[i] > 0.0f ? 1 : 0;
  return c;
}

namespace {
const char* image_dir() {
  const char* dir = std::getenv("MPG_TEST_IMAGES");
  if (dir) std::filesystem::create_directories(dir);
  return dir;
}
}  // namespace

void save_for_inspection(const std::string& name, const metrics::MaskImage& image) {
  const char* dir = image_dir();
  if (dir && image.width > 0) (void)metrics::write_png(std::string(dir) + "/" + name + ".png", image);
}

void save_for_inspection(const std::string& name, const metrics::RgbaImage& image) {
  const char* dir = image_dir();
  if (dir && image.width > 0) (void)metrics::write_png(std::string(dir) + "/" + name + ".png", image);
}

}  // namespace penumbra::test
