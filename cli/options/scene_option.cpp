#include "cli/options/scene_option.h"

#include <cstdio>

#include "scene/builtin_scenes.h"
#include "scene/load_scene.h"

namespace penumbra::cli {

namespace {

// Coordinates beyond this have no float precision left to place a camera or light with.
constexpr double kMaxCoordinate = 1e6;

std::string vec3_text(const glm::vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.6g,%.6g,%.6g", v.x, v.y, v.z);
  return buf;
}

}  // namespace

OptionSpec scene_name_option() {
  std::string names;
  for (const std::string& n : scene::builtin_scene_names()) names += (names.empty() ? "" : ", ") + n;
  return {"scene", true, false, "NAME[:k=v,...]|FILE",
          "built-in scene (" + names + "), its parameters set after ':' (room:lamp_height=2), or .gltf/.glb"};
}

std::vector<OptionSpec> scene_option_specs() {
  return {
      {"camera", true, false, "C",
       "scene (default: a built-in's own, a glTF fitted to the model), fit, file[:N|:NAME] (a camera the glTF "
       "places), or X,Y,Z:TX,TY,TZ (position looking at target, world units)"},
      {"light-dir", true, false, "X,Y,Z", "light direction (light -> scene); a directional emitter keeps its distance; an error for a point light"},
      {"light-size", true, false, "S", "emitter diameter, world units; 0 = hard shadows"},
      {"ground", true, false, "on|off", "a plane under models that have no floor (default on)"},
  };
}

std::vector<OptionSpec> with_scene_options(std::vector<OptionSpec> specs) {
  for (OptionSpec& s : scene_option_specs()) specs.push_back(std::move(s));
  return specs;
}

Result<glm::vec3> parse_vec3(const std::string& option, const std::string& text) {
  glm::vec3 v(0.0f);
  size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t comma = text.find(',', start);
    if ((i < 2) != (comma != std::string::npos))
      return make_error("--" + option + " expects three numbers X,Y,Z, got '" + shortened(text) + "'");
    auto n = parse_real(option, text.substr(start, i < 2 ? comma - start : std::string::npos), -kMaxCoordinate,
                        kMaxCoordinate);
    if (!n) {
      Error e = n.error();
      e.message = "--" + option + " expects three numbers X,Y,Z within +-1e6, got '" + shortened(text) + "'";
      return e;
    }
    v[i] = static_cast<float>(*n);
    start = comma + 1;
  }
  return v;
}

Result<scene::CameraChoice> parse_camera_choice(const std::string& text) {
  scene::CameraChoice c;
  if (text == "scene") return c;
  if (text == "fit") {
    c.kind = scene::CameraChoice::Kind::fitted;
    return c;
  }
  if (text == "file" || text.rfind("file:", 0) == 0) {
    c.kind = scene::CameraChoice::Kind::file;
    c.file_camera = text.size() > 5 ? text.substr(5) : "";
    return c;
  }
  const size_t colon = text.find(':');
  if (colon == std::string::npos)
    return make_error("--camera expects scene, fit, file[:N|:NAME] or X,Y,Z:TX,TY,TZ, got '" + shortened(text) + "'");
  auto position = parse_vec3("camera", text.substr(0, colon));
  if (!position) return position.error();
  auto target = parse_vec3("camera", text.substr(colon + 1));
  if (!target) return target.error();
  if (glm::length(*target - *position) < 1e-6f)
    return make_error("--camera: the target equals the position in '" + shortened(text) + "'");
  c.kind = scene::CameraChoice::Kind::pose;
  c.position = *position;
  c.target = *target;
  return c;
}

Result<SceneOptions> parse_scene_options(const ParsedArgs& args) {
  SceneOptions o;
  if (auto v = args.get("camera")) {
    auto c = parse_camera_choice(*v);
    if (!c) return c.error();
    o.staging.camera = *c;
  }
  if (auto v = args.get("light-dir")) {
    auto d = parse_vec3("light-dir", *v);
    if (!d) return d.error();
    if (glm::length(*d) < 1e-6f) return make_error("--light-dir must not be the zero vector");
    o.staging.light_direction = glm::normalize(*d);
  }
  if (auto v = args.get("light-size")) {
    auto size = parse_real("light-size", *v, 0.0, kMaxCoordinate);
    if (!size) return size.error();
    o.staging.light_size = static_cast<float>(*size);
  }
  if (auto v = args.get("ground")) {
    if (*v != "on" && *v != "off") return make_error("--ground expects on or off, got '" + shortened(*v) + "'");
    o.staging.ground = *v == "on";
  }
  return o;
}

Result<scene::Scene> load_scene_option(const std::string& name_or_path, const SceneOptions& options, int width,
                                       int height) {
  Result<scene::Scene> s = scene::load_scene(name_or_path);
  if (!s) return s;
  scene::StagingOptions staging = options.staging;
  staging.aspect = height > 0 ? static_cast<float>(width) / static_cast<float>(height) : staging.aspect;
  if (Status st = scene::stage_scene(*s, staging); !st) return st.error();
  return s;
}

Result<scene::Scene> load_scene_option(const std::string& name_or_path, const ParsedArgs& args, int width,
                                       int height) {
  auto options = parse_scene_options(args);
  if (!options) return options.error();
  return load_scene_option(name_or_path, *options, width, height);
}

Result<scene::Scene> load_scene_option(const std::string& name_or_path) {
  return load_scene_option(name_or_path, SceneOptions{}, 16, 9);
}

std::string scene_options_text(const scene::Camera& camera, const scene::Light& light, bool ground) {
  char size[32];
  std::snprintf(size, sizeof size, "%.6g", light.size);
  return "--camera " + vec3_text(camera.position) + ":" + vec3_text(camera.position + camera.forward()) +
         " --light-dir " + vec3_text(light.direction) + " --light-size " + size + " --ground " +
         (ground ? "on" : "off");
}

}  // namespace penumbra::cli
