#include "test_support/technique_rig.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

#include "exec/gbuffer_readback.h"
#include "passes/shared_passes.h"
#include "plugin/plugin_library.h"
#include "scene/builtin_scenes.h"
#include "test_support/gl_context.h"

namespace penumbra::test {

struct TechniqueRig::State {
  technique::TechniqueRegistry registry;
  exec::PassLibrary library;
};

TechniqueRig::TechniqueRig(RigOptions options)
    : state_(std::make_unique<State>()), technique_(std::move(options.technique)) {
  gl_context();
  if (options.techniques) options.techniques(state_->registry);
  if (Result<int> loaded = plugin::load_plugins(options.plugin_dirs, state_->registry); !loaded)
    ADD_FAILURE() << loaded.error().to_string();
  state_->library = make_pass_library(state_->registry);
  session_ = std::make_unique<technique::TechniqueSession>(state_->registry, state_->library);
  session_->compile_options().keep_alive = {"gbuffer_depth", "gbuffer_normal"};
  for (std::string& r : options.keep_alive) session_->compile_options().keep_alive.push_back(std::move(r));
  resize(options.width, options.height);
  set_shadow_size(options.shadow_size);
}

TechniqueRig::~TechniqueRig() = default;

const technique::TechniqueRegistry& TechniqueRig::registry() const { return state_->registry; }

void TechniqueRig::set_scene(const scene::Scene& scene) {
  session_->set_scene(scene);
  if (session_->technique().empty() && !technique_.empty()) use(technique_);
}

void TechniqueRig::use(const std::string& technique) {
  Status s = session_->set_technique(technique);
  EXPECT_TRUE(s) << technique << ": " << s.error().to_string() << "\n" << s.error().details;
}

void TechniqueRig::set(const std::vector<std::string>& assignments) {
  for (const std::string& a : assignments) {
    Status s = session_->set_param(a);
    EXPECT_TRUE(s) << a << ": " << s.error().to_string() << "\n" << s.error().details;
  }
}

void TechniqueRig::resize(int width, int height) {
  Status s = session_->resize(width, height);
  EXPECT_TRUE(s) << s.error().to_string();
}

void TechniqueRig::set_shadow_size(int texels) {
  Status s = session_->set_shadow_size(texels);
  EXPECT_TRUE(s) << s.error().to_string();
}

void TechniqueRig::render(int frames) {
  for (int i = 0; i < frames; ++i) {
    Status s = session_->render();
    EXPECT_TRUE(s) << session_->technique() << ": " << s.error().to_string();
    if (!s) return;
    // GPU timestamps are collected a few frames late and dropped when not yet available (the
    // pass timer never stalls); finishing each frame makes every sample available.
    glFinish();
  }
}

RenderedFrame TechniqueRig::render_frame(const scene::Scene& scene, const std::string& technique,
                                         const std::vector<std::string>& settings, int frames) {
  RenderedFrame f;
  session_->set_scene(scene);
  if (Status s = session_->set_technique(technique); !s) {
    ADD_FAILURE() << technique << ": " << s.error().to_string() << "\n" << s.error().details;
    return f;
  }
  set(settings);
  render(frames);
  f.technique_ms = technique_ms(&f.pass_ms);
  f.mask = shadow_mask();
  gbuffer(f.positions, f.normals, f.coverage);
  f.geometry = metrics::receiver_geometry(f.mask.width, f.mask.height, positions(), f.normals, session_->light());
  return f;
}

metrics::MaskImage TechniqueRig::read(const std::string& resource, int channel) {
  gl::Texture* t = session_->executor().resource(resource);
  return t ? read_channel(*t, channel) : metrics::MaskImage{};
}

TextureImage TechniqueRig::read_all(const std::string& resource) {
  gl::Texture* t = session_->executor().resource(resource);
  return t ? read_texture(*t) : TextureImage{};
}

metrics::RgbaImage TechniqueRig::read_rgba(const std::string& resource) {
  gl::Texture* t = session_->executor().resource(resource);
  return t ? read_rgba8(*t) : metrics::RgbaImage{};
}

metrics::CoverageMask TechniqueRig::coverage() {
  const metrics::MaskImage d = read("gbuffer_depth");
  metrics::CoverageMask c(d.pixels.size(), 0);
  for (size_t i = 0; i < c.size(); ++i) c[i] = d.pixels[i] > 0.0f ? 1 : 0;
  return c;
}

std::vector<glm::vec4> TechniqueRig::positions() {
  gl::Texture* depth = session_->executor().resource("gbuffer_depth");
  return depth ? exec::read_positions(*depth, session_->camera(), exec::RowOrder::top_down) : std::vector<glm::vec4>{};
}

metrics::MaskImage TechniqueRig::world_y() {
  metrics::MaskImage y = read("gbuffer_depth");
  const std::vector<glm::vec4> p = positions();
  for (size_t i = 0; i < y.pixels.size() && i < p.size(); ++i)
    y.pixels[i] = p[i].w > 0.0f ? p[i].y : std::numeric_limits<float>::quiet_NaN();
  return y;
}

void TechniqueRig::gbuffer(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                           metrics::CoverageMask& coverage) {
  positions.clear();
  normals.clear();
  coverage.clear();
  const std::vector<glm::vec4> p = this->positions();
  const TextureImage n = read_all("gbuffer_normal");
  if (p.empty() || n.texels.empty()) {
    ADD_FAILURE() << "the frame has no gbuffer_depth or gbuffer_normal";
    return;
  }
  const size_t count = p.size();
  positions.resize(count);
  normals.resize(count);
  coverage.resize(count);
  for (size_t i = 0; i < count; ++i) {
    coverage[i] = p[i].w > 0.0f ? 1 : 0;
    positions[i] = coverage[i] ? glm::vec3(p[i]) : glm::vec3(0.0f);
    normals[i] = exec::decode_octahedral_normal({n.texels[2 * i], n.texels[2 * i + 1]});
  }
}

double TechniqueRig::technique_ms(std::string* pass_ms) const {
  double total = 0.0;
  for (const exec::PassTiming& t : session_->executor().timings()) {
    if (t.name == "gbuffer" || t.name == "lighting") continue;
    total += t.median_ms();
    if (pass_ms) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%s%s %.3f", pass_ms->empty() ? "" : ", ", t.name.c_str(), t.median_ms());
      *pass_ms += buf;
    }
  }
  return total;
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
