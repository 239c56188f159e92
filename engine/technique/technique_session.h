#pragma once
// One live technique in a frame: the object the CLI, the sandbox and the tests drive.
// It owns the executor, texture pool and shader cache, composes the technique's graph into
// the frame (frame_graph.h), recompiles when a structural parameter, the technique, the screen
// or shadow-map size or a debug switch changes, and otherwise only updates values, which the
// plan reads per frame.
//
//   technique::TechniqueSession session(registry, library);
//   session.set_scene(*scene::load_scene("ball"));
//   session.set_technique("pcss");
//   session.set_param("blocker_samples=32");
//   session.resize(512, 512);
//   if (Status s = session.render(); !s) report(s.error());
//   gl::Texture* mask = session.executor().resource("shadow_mask");
#include <memory>
#include <optional>
#include <string>

#include "exec/executor.h"
#include "exec/gpu_scene.h"
#include "graph/compiler.h"
#include "graph/parameters.h"
#include "scene/cascades.h"
#include "technique/technique.h"

namespace penumbra::technique {

class TechniqueSession {
 public:
  TechniqueSession(const TechniqueRegistry& registry, const exec::PassLibrary& library);

  // Uploads the scene; camera and light reset to the scene's defaults.
  void set_scene(const scene::Scene& scene);
  bool has_scene() const { return gpu_scene_ != nullptr; }
  const scene::Scene& scene() const { return gpu_scene_->cpu(); }

  // Loads and compiles the technique; parameters start at their defaults. On error the
  // previous technique stays active.
  Status set_technique(const std::string& name);
  const std::string& technique() const { return technique_; }

  // "k=v"; a structural parameter recompiles. Errors name the key and the valid range.
  Status set_param(const std::string& assignment);
  Status set_param(const std::string& name, const graph::ParamValue& value);
  // A preset {"k": v, ...}; all-or-nothing.
  Status apply_preset(const std::string& json_text);
  Status reset_params();
  const graph::ParameterSet& params() const { return params_; }

  Status resize(int width, int height);
  Status set_shadow_size(int texels);
  // Cascaded shadow maps for a directional light (scene/cascades.h); 1 cascade (the default) is
  // one map over the scene. Errors: settings out of range. A frame with cascades under a light
  // that is not directional fails with a bad-input Error.
  Status set_cascades(const scene::CascadeSettings& cascades);
  const scene::CascadeSettings& cascades() const { return cascades_; }
  const graph::CompileSettings& settings() const { return settings_; }
  // Debug switches and keep-alive list; call recompile() after changing them.
  graph::CompileOptions& compile_options() { return options_; }
  Status recompile();

  scene::Camera& camera() { return camera_; }
  scene::Light& light() { return light_; }

  // Executes one frame of the compiled plan.
  Status render();

  exec::Executor& executor() { return executor_; }
  exec::ShaderCache& shaders() { return shaders_; }
  exec::TexturePool& pool() { return pool_; }
  const graph::CompiledPlan& plan() const { return executor_.plan(); }
  const graph::GraphDesc& graph() const { return graph_; }
  // How far the technique's progressive pass (one that refines its result over frames, such as
  // the reference's) has got: the last progress a pass reported since the last compile; none
  // for a technique without one (exec/pass_progress.h).
  const std::optional<exec::PassProgress>& progress() const { return executor_.progress(); }
  // Number of successful compiles so far (tests: uniform changes must not recompile).
  int compile_count() const { return compile_count_; }

 private:
  Status compile_current();

  const TechniqueRegistry& registry_;
  const exec::PassLibrary& library_;
  exec::ShaderCache shaders_;
  exec::TexturePool pool_;
  exec::Executor executor_;
  std::unique_ptr<exec::GpuScene> gpu_scene_;
  scene::Camera camera_;
  scene::Light light_;
  std::string technique_;
  graph::GraphDesc graph_;  // composed frame graph
  graph::ParameterSet params_;
  graph::CompileSettings settings_{512, 512, 2048};
  scene::CascadeSettings cascades_;
  graph::CompileOptions options_;
  std::uint32_t frame_ = 0;
  int compile_count_ = 0;
};

// Turns every error of a failed compile into one Error (first error, all of them in details).
Error errors_to_error(const graph::GraphErrors& errors);

}  // namespace penumbra::technique
