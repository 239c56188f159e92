#pragma once
// The generic technique rig: scene + technique + settings + frame -> the shadow mask and any
// resource of that frame, read back as CPU images (rows top to bottom, read_back.h). It owns a
// technique registry, the pass library and one technique::TechniqueSession on the test GL context
// (gl_context.h); every failure fails the current test with the error's text.
//
//   TechniqueRig rig({.width = 160, .height = 120, .technique = "vsm",
//                     .techniques = vsm::register_technique});
//   rig.set_scene(*scene::make_builtin_scene("ball"));
//   rig.set({"blur_radius=2"});
//   rig.render();
//   metrics::MaskImage mask = rig.shadow_mask();               // 1 = lit
//   metrics::MaskImage moments = rig.read("moments", 1);       // any resource, one channel
//
// docs/testing.md walks through a complete test.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "metrics/pixel_classes.h"
#include "technique/technique_session.h"
#include "scene/scene.h"
#include "test_support/read_back.h"

namespace penumbra::test {

struct RigOptions {
  int width = 128, height = 128;  // screen, pixels
  int shadow_size = 1024;         // shadow map, texels
  // Selected by set_scene() while none is (empty: call use()).
  std::string technique;
  // The techniques the rig can run: none unless given. A plugin's tests pass its register
  // function; the repository's tests pass register_builtin_techniques.
  std::function<void(technique::TechniqueRegistry&)> techniques;
  // Plugin directories loaded after `techniques` (plugin::load_plugins: --plugin-dir's rules).
  std::vector<std::string> plugin_dirs;
  // Resources kept alive for read() besides the outputs and gbuffer_depth/gbuffer_normal
  // (transient textures are otherwise reused by later passes of the frame).
  std::vector<std::string> keep_alive;
};

// One frame read back (rigs' render_frame()).
struct RenderedFrame {
  metrics::MaskImage mask;           // shadow_mask, 1 = lit
  std::vector<glm::vec3> positions;  // world; (0, 0, 0) where coverage is 0
  std::vector<glm::vec3> normals;
  metrics::CoverageMask coverage;    // gbuffer_depth > 0: receivers
  // The receivers' view depth, normals and facing towards the light (metrics::receiver_geometry):
  // what the pixel classes of a penumbra metric need (reference_comparison.h).
  metrics::ReceiverGeometry geometry;
  // Sum of the median times of the technique's own passes (all but gbuffer and lighting), ms:
  // GPU timestamps on a GPU, glFinish + a CPU clock on llvmpipe.
  double technique_ms = 0.0;
  std::string pass_ms;  // "shadow_map 0.112, pcf_mask 0.054": those passes' medians
};

class TechniqueRig {
 public:
  explicit TechniqueRig(RigOptions options = {});
  ~TechniqueRig();

  technique::TechniqueSession& session() { return *session_; }
  const technique::TechniqueRegistry& registry() const;

  // Uploads the scene (camera and light reset to the scene's); selects options.technique if no
  // technique is selected yet.
  void set_scene(const scene::Scene& scene);
  // Selects a technique, its parameters at their defaults.
  void use(const std::string& technique);
  // Each "k=v", as after --set.
  void set(const std::vector<std::string>& assignments);
  void resize(int width, int height);
  void set_shadow_size(int texels);
  // `frames` frames, each finished (glFinish) so every pass timing is collected.
  void render(int frames = 1);
  // One frame, its Status returned instead of failing the test (bad-input tests).
  Status try_render() { return session_->render(); }

  // In one call: the scene, the technique, its settings ("k=v"), `frames` frames, read back.
  RenderedFrame render_frame(const scene::Scene& scene, const std::string& technique,
                             const std::vector<std::string>& settings = {}, int frames = 1);

  // --- the last frame, rows top to bottom ------------------------------------------------
  // One channel of a resource (a channel past its last reads the last); empty when absent.
  metrics::MaskImage read(const std::string& resource, int channel = 0);
  metrics::MaskImage shadow_mask() { return read("shadow_mask"); }
  // Every channel of a resource; empty when absent.
  TextureImage read_all(const std::string& resource);
  // A 4-channel resource as RGBA8 (debug views); empty when absent or not 4 channels.
  metrics::RgbaImage read_rgba(const std::string& resource);
  // Receivers: 1 where gbuffer_depth > 0.
  metrics::CoverageMask coverage();
  // World positions rebuilt from gbuffer_depth (w = view depth, 0 on background).
  std::vector<glm::vec4> positions();
  // World-space height per pixel, NaN on background.
  metrics::MaskImage world_y();
  // G-buffer positions ((0, 0, 0) off receivers), normals and coverage, e.g. for the ray-traced
  // reference (reference::trace_visibility).
  void gbuffer(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals, metrics::CoverageMask& coverage);
  // The technique's own passes' median times (see RenderedFrame).
  double technique_ms(std::string* pass_ms = nullptr) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::unique_ptr<technique::TechniqueSession> session_;
  std::string technique_;
};

// A built-in scene (scene/builtin_scenes.h) with its parameters; fails the test on error.
scene::Scene builtin_scene(const std::string& name, const std::map<std::string, float>& params = {});

// World position -> pixel coordinates of `camera` at width x height (top-left origin, pixel
// centres at +0.5), as metrics::penumbra_width expects.
glm::vec2 project_to_pixel(const scene::Camera& camera, const glm::vec3& world, int width, int height);

}  // namespace penumbra::test
