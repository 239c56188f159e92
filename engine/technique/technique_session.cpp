#include "technique/technique_session.h"

#include "technique/frame_graph.h"

namespace penumbra::technique {

Error errors_to_error(const graph::GraphErrors& errors) {
  if (errors.empty()) return make_error("graph failed to compile", ErrorKind::internal);
  Error e = errors.front();
  std::string all;
  for (const auto& err : errors) all += err.to_string() + "\n";
  if (errors.size() > 1) e.message += " (and " + std::to_string(errors.size() - 1) + " more)";
  e.details = all;
  return e;
}

TechniqueSession::TechniqueSession(const TechniqueRegistry& registry, const exec::PassLibrary& library)
    : registry_(registry), library_(library), executor_(library, shaders_, pool_) {}

void TechniqueSession::set_scene(const scene::Scene& scene) {
  gpu_scene_ = std::make_unique<exec::GpuScene>(scene);
  camera_ = scene.camera;
  light_ = scene.light;
}

Status TechniqueSession::compile_current() {
  auto plan = graph::compile(graph_, library_.declarations(), params_, settings_, options_);
  if (!plan) return errors_to_error(plan.errors());
  if (Status s = executor_.set_plan(std::move(*plan)); !s) return s;
  ++compile_count_;
  return {};
}

Status TechniqueSession::set_technique(const std::string& name) {
  const Technique* t = registry_.find(name);
  if (!t) {
    std::string valid;
    for (const std::string& n : registry_.names()) valid += (valid.empty() ? "" : ", ") + n;
    return make_error("unknown technique '" + name + "' (available: " + valid + ")");
  }
  auto declared = load_technique_graph(*t, library_.declarations());
  if (!declared) return declared.error();
  auto composed = compose_frame_graph(*declared);
  if (!composed) return composed.error();
  graph::GraphDesc old_graph = std::move(graph_);
  graph::ParameterSet old_params = params_;
  graph_ = std::move(*composed);
  params_ = graph::ParameterSet(graph_.parameters);
  if (Status s = compile_current(); !s) {
    graph_ = std::move(old_graph);
    params_ = std::move(old_params);
    return s;
  }
  technique_ = name;
  return {};
}

Status TechniqueSession::set_param(const std::string& name, const graph::ParamValue& value) {
  const graph::ParamDesc* desc = params_.find(name);
  graph::ParameterSet before = params_;
  if (Status s = params_.set(name, value); !s) return s;
  if (desc && desc->structural) {
    if (Status s = compile_current(); !s) {
      params_ = std::move(before);
      return s;
    }
  }
  return {};
}

Status TechniqueSession::set_param(const std::string& assignment) {
  auto eq = assignment.find('=');
  std::string name = eq == std::string::npos ? assignment : assignment.substr(0, eq);
  graph::ParameterSet before = params_;
  if (Status s = params_.set_from_string(assignment); !s) return s;
  const graph::ParamDesc* desc = params_.find(name);
  if (desc && desc->structural) {
    if (Status s = compile_current(); !s) {
      params_ = std::move(before);
      return s;
    }
  }
  return {};
}

Status TechniqueSession::apply_preset(const std::string& json_text) {
  graph::ParameterSet before = params_;
  if (Status s = params_.apply_json(json_text); !s) return s;
  if (Status s = compile_current(); !s) {
    params_ = std::move(before);
    return s;
  }
  return {};
}

Status TechniqueSession::reset_params() {
  params_.reset_all();
  return compile_current();
}

Status TechniqueSession::resize(int width, int height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    return make_error("screen size " + std::to_string(width) + "x" + std::to_string(height) +
                      " is outside [1, 16384]");
  if (settings_.screen_w == width && settings_.screen_h == height) return {};
  settings_.screen_w = width;
  settings_.screen_h = height;
  return technique_.empty() ? Status{} : compile_current();
}

Status TechniqueSession::set_shadow_size(int texels) {
  if (texels < 16 || texels > 16384)
    return make_error("shadow-map size " + std::to_string(texels) + " is outside [16, 16384] texels");
  if (settings_.shadow_size == texels) return {};
  settings_.shadow_size = texels;
  return technique_.empty() ? Status{} : compile_current();
}

Status TechniqueSession::set_cascades(const scene::CascadeSettings& cascades) {
  if (Status s = scene::check_cascade_settings(cascades); !s) return s;
  // The shaders' variant follows the count (PassContext::program), so no recompile is needed.
  cascades_ = cascades;
  return {};
}

Status TechniqueSession::recompile() { return technique_.empty() ? Status{} : compile_current(); }

Status TechniqueSession::render() {
  if (!gpu_scene_) return make_error("no scene set", ErrorKind::internal);
  if (technique_.empty()) return make_error("no technique set", ErrorKind::internal);
  exec::FrameInputs frame;
  frame.scene = gpu_scene_.get();
  frame.camera = camera_;
  frame.light = light_;
  frame.shadow = scene::shadow_frustum(light_, gpu_scene_->cpu().bounds);
  frame.screen_w = settings_.screen_w;
  frame.screen_h = settings_.screen_h;
  frame.shadow_size = settings_.shadow_size;
  Result<scene::ShadowCascades> cascades = scene::shadow_cascades(light_, frame.shadow, camera_, frame.aspect(),
                                                                  gpu_scene_->cpu().bounds, cascades_,
                                                                  settings_.shadow_size);
  if (!cascades) return cascades.error();
  frame.cascades = *cascades;
  frame.frame_index = frame_++;
  return executor_.execute(params_, frame);
}

}  // namespace penumbra::technique
