#include "baseline_frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "scene/builtin_scenes.h"
#include "test_support/gl_context.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {
namespace {

// GL reads rows bottom to top; the metrics use top to bottom.
std::vector<float> read_flipped(const gl::Texture& t) {
  std::vector<float> gl_rows = t.read();
  const int c = t.info().channels, w = t.width(), h = t.height();
  std::vector<float> out(gl_rows.size());
  for (int y = 0; y < h; ++y)
    std::copy_n(gl_rows.begin() + static_cast<size_t>(h - 1 - y) * w * c, static_cast<size_t>(w) * c,
                out.begin() + static_cast<size_t>(y) * w * c);
  return out;
}

}  // namespace

BaselineRenderer::BaselineRenderer() {
  gl_context();
  register_builtin_techniques(registry_);
  library_ = make_pass_library(registry_);
  session_ = std::make_unique<plugin::TechniqueSession>(registry_, library_);
}

RenderedFrame BaselineRenderer::render(const scene::Scene& scene, const std::string& technique,
                                       const std::map<std::string, std::string>& params, int width,
                                       int height, int frames, int shadow_size) {
  RenderedFrame f;
  plugin::TechniqueSession& s = *session_;
  s.set_scene(scene);
  EXPECT_TRUE(s.resize(width, height));
  EXPECT_TRUE(s.set_shadow_size(shadow_size));
  if (Status st = s.set_technique(technique); !st) {
    ADD_FAILURE() << technique << ": " << st.error().to_string();
    return f;
  }
  for (const auto& [k, v] : params)
    if (Status st = s.set_param(k + "=" + v); !st) ADD_FAILURE() << st.error().to_string();
  for (int i = 0; i < frames; ++i) {
    if (Status st = s.render(); !st) {
      ADD_FAILURE() << technique << " on " << scene.name << ": " << st.error().to_string();
      return f;
    }
    // GPU timestamps are collected a few frames late and dropped when not yet available (the
    // pass timer never stalls); finishing each frame here makes every sample available.
    glFinish();
  }
  for (const exec::PassTiming& t : s.executor().timings())
    if (t.name != "gbuffer" && t.name != "lighting") {
      f.technique_ms += t.median_ms();
      char buf[96];
      std::snprintf(buf, sizeof buf, "%s%s %.3f", f.pass_ms.empty() ? "" : ", ", t.name.c_str(), t.median_ms());
      f.pass_ms += buf;
    }

  gl::Texture* mask = s.executor().resource("shadow_mask");
  gl::Texture* pos = s.executor().resource("gbuffer_position");
  gl::Texture* nrm = s.executor().resource("gbuffer_normal");
  if (!mask || !pos || !nrm) {
    ADD_FAILURE() << "missing shadow_mask / gbuffer_position / gbuffer_normal";
    return f;
  }
  f.mask = metrics::MaskImage(width, height);
  f.mask.pixels = read_flipped(*mask);
  std::vector<float> p = read_flipped(*pos), n = read_flipped(*nrm);
  const size_t count = static_cast<size_t>(width) * height;
  f.positions.resize(count);
  f.normals.resize(count);
  f.coverage.resize(count);
  for (size_t i = 0; i < count; ++i) {
    f.coverage[i] = p[4 * i + 3] > 0.0f ? 1 : 0;
    f.positions[i] = f.coverage[i] ? glm::vec3(p[4 * i], p[4 * i + 1], p[4 * i + 2]) : glm::vec3(0.0f);
    f.normals[i] = glm::vec3(n[4 * i], n[4 * i + 1], n[4 * i + 2]);
  }
  return f;
}

scene::Scene builtin_scene(const std::string& name, const std::map<std::string, float>& params) {
  Result<scene::Scene> s = scene::make_builtin_scene(name, params);
  EXPECT_TRUE(s) << (s ? "" : s.error().to_string());
  return s ? std::move(*s) : scene::Scene{};
}

glm::vec2 project_to_pixel(const scene::Camera& camera, const glm::vec3& world, int width, int height) {
  glm::vec4 clip = camera.projection(float(width) / float(height)) * camera.view() * glm::vec4(world, 1.0f);
  glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * width, (0.5f - ndc.y * 0.5f) * height};
}

}  // namespace penumbra::test
