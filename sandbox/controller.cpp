#include "sandbox/controller.h"

#include "sandbox/viewed_resource.h"
#include "sandbox/inspector.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "measurement/reference_frame.h"
#include "technique/preset.h"
#include "util/file_write.h"
#include "util/file_read.h"
#include "technique/frame_graph.h"
#include "scene/ground_plane.h"
#include "scene/load_scene.h"
#include "gl/debug_output.h"
#include "util/png.h"
#include "passes/shared_passes.h"

namespace penumbra::sandbox {


SandboxController::SandboxController(const technique::TechniqueRegistry& registry,
                                     const exec::PassLibrary& library)
    : registry_(registry), library_(library),
      primary_(std::make_unique<technique::TechniqueSession>(registry, library)) {}

SandboxController::~SandboxController() = default;

Status SandboxController::note(Status s) {
  message_ = s ? std::string() : s.error().to_string();
  return s;
}

Status SandboxController::init(const std::string& scene, const std::string& technique, int width,
                               int height) {
  if (Status s = resize(width, height); !s) return s;
  if (Status s = load_scene(scene); !s) return s;
  std::string t = technique;
  if (t.empty()) {
    const std::vector<std::string> names = registry_.names();
    if (names.empty())
      return make_error("no techniques are registered (register_builtin_techniques added none)",
                        ErrorKind::internal);
    const bool has_default = std::find(names.begin(), names.end(), kStartTechnique) != names.end();
    t = has_default ? kStartTechnique : names.front();
  }
  return set_technique(t);
}

// --- scene, camera, light ---------------------------------------------------------------------

Status SandboxController::load_scene(const std::string& name_or_path) {
  scene::StagingOptions staging = staging_;
  if (!scene_name_.empty() && name_or_path != scene_name_) {
    staging.camera = {};
    staging.light_direction.reset();
    staging.light_size.reset();
  }
  staging.aspect = height_ > 0 ? static_cast<float>(width_) / static_cast<float>(height_) : staging.aspect;
  Result<scene::Scene> loaded = scene::load_scene(name_or_path);
  if (!loaded) return note(loaded.error());
  if (Status s = scene::stage_scene(*loaded, staging); !s) return note(s);
  primary_->set_scene(*loaded);
  for (technique::TechniqueSession* s : partners()) s->set_scene(*loaded);
  scene_name_ = name_or_path;
  staging_ = staging;
  if (loaded->light.type != scene::LightType::directional && primary_->cascades().count > 1) {
    scene::CascadeSettings one = primary_->cascades();
    one.count = 1;
    if (Status s = set_cascades(one); !s) return s;
    return note(make_error("cascades are for directional lights: back to one shadow map for this scene's " +
                           std::string(scene::light_type_name(loaded->light.type)) + " light", ErrorKind::bad_input));
  }
  return note({});
}

Status SandboxController::set_ground(bool on) {
  const bool was = staging_.ground;
  staging_.ground = on;
  if (scene_name_.empty()) return note({});
  Status s = load_scene(scene_name_);
  if (!s) staging_.ground = was;
  return s;
}

Status SandboxController::set_camera_choice(const scene::CameraChoice& choice) {
  const scene::CameraChoice was = staging_.camera;
  staging_.camera = choice;
  if (scene_name_.empty()) return note({});
  Status s = load_scene(scene_name_);
  if (!s) staging_.camera = was;
  return s;
}

const std::vector<scene::SceneCamera>& SandboxController::file_cameras() const {
  static const std::vector<scene::SceneCamera> kNone;
  return primary_->has_scene() ? primary_->scene().cameras : kNone;
}

bool SandboxController::ground_added() const {
  return primary_->has_scene() && scene::has_added_ground_plane(primary_->scene());
}

void SandboxController::move_camera(const glm::vec3& axes, float dt, bool fast) {
  scene::Camera& cam = camera();
  const glm::vec3 forward = cam.forward();
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  // Half the scene's bounding radius per second feels right from a fence to a courtyard.
  float speed = primary_->has_scene() ? std::max(0.5f * primary_->scene().bounds.radius(), 0.5f) : 1.0f;
  if (fast) speed *= 4.0f;
  cam.position += (axes.x * right + axes.y * glm::vec3(0, 1, 0) + axes.z * forward) * speed * dt;
}

void SandboxController::look(float dx, float dy) {
  constexpr float kRadiansPerPixel = 0.003f;
  scene::Camera& cam = camera();
  cam.yaw += dx * kRadiansPerPixel;
  cam.pitch = std::clamp(cam.pitch - dy * kRadiansPerPixel, -1.55f, 1.55f);
}

Status SandboxController::set_camera(const std::optional<glm::vec3>& position,
                                     const std::optional<glm::vec3>& look_at,
                                     std::optional<float> yaw_deg, std::optional<float> pitch_deg) {
  scene::Camera& cam = camera();
  if (position) cam.position = *position;
  if (look_at) {
    if (glm::length(*look_at - cam.position) < 1e-6f)
      return note(make_error("camera look_at point equals the camera position"));
    scene::Camera aimed = scene::Camera::look_at(cam.position, *look_at, cam.fov_y, cam.near_plane,
                                                 cam.far_plane);
    cam.yaw = aimed.yaw;
    cam.pitch = aimed.pitch;
  }
  if (yaw_deg) cam.yaw = glm::radians(*yaw_deg);
  if (pitch_deg) cam.pitch = std::clamp(glm::radians(*pitch_deg), -1.55f, 1.55f);
  return note({});
}

Status SandboxController::light_change_allowed() {
  if (light_frozen_) return note(make_error("the light is frozen: untick 'freeze light' in the Light panel first"));
  return {};
}

Status SandboxController::set_light_direction(glm::vec3 direction) {
  if (Status s = light_change_allowed(); !s) return s;
  if (glm::length(direction) < 1e-6f) return note(make_error("the light direction must not be zero"));
  direction = glm::normalize(direction);
  scene::Light& l = light();
  if (l.type == scene::LightType::directional && primary_->has_scene()) {
    // Keep the emitter disk at its distance from the scene centre, now along -direction.
    const glm::vec3 c = primary_->scene().bounds.center();
    float distance = std::max(glm::length(l.position - c), 2.0f * primary_->scene().bounds.radius());
    l.position = c - direction * distance;
  }
  l.direction = direction;
  return {};
}

Status SandboxController::set_light_position(const glm::vec3& position) {
  if (Status s = light_change_allowed(); !s) return s;
  light().position = position;
  return {};
}

Status SandboxController::set_spot_angle(float radians) {
  if (Status s = light_change_allowed(); !s) return s;
  if (Status s = scene::check_spot_angle_degrees(glm::degrees(radians)); !s) return s;
  light().spot_angle = radians;
  return {};
}

Status SandboxController::set_light_type(scene::LightType type) {
  if (Status s = light_change_allowed(); !s) return s;
  light().type = type;
  return {};
}

Status SandboxController::set_light_size(float diameter) {
  if (Status s = light_change_allowed(); !s) return s;
  if (!(diameter >= 0.0f) || !std::isfinite(diameter))
    return note(make_error("light size must be >= 0 (emitter disk diameter, world units)"));
  light().size = diameter;
  return note({});
}

Status SandboxController::align_light_with_camera() {
  if (Status s = light_change_allowed(); !s) return s;
  if (light().type != scene::LightType::directional) {  // spot and point lights move to the camera
    light().position = camera().position;
    light().direction = camera().forward();
    return {};
  }
  return set_light_direction(camera().forward());
}

Status SandboxController::set_shadow_size(int texels) {
  if (Status s = primary_->set_shadow_size(texels); !s) return note(s);
  for (technique::TechniqueSession* p : partners())
    if (Status s = p->set_shadow_size(texels); !s) return note(s);
  return note({});
}

Status SandboxController::set_cascades(const scene::CascadeSettings& cascades) {
  if (Status s = primary_->set_cascades(cascades); !s) return note(s);
  for (technique::TechniqueSession* p : partners())
    if (Status s = p->set_cascades(cascades); !s) return note(s);
  return note({});
}

// --- technique and parameters -----------------------------------------------------------------

const std::string& SandboxController::technique_description(const std::string& name) const {
  auto it = descriptions_.find(name);
  if (it != descriptions_.end()) return it->second;
  std::string text;
  if (const technique::Technique* t = registry_.find(name))
    if (auto g = technique::load_technique_graph(*t, library_.declarations())) text = g->description;
  return descriptions_.emplace(name, std::move(text)).first->second;
}

Status SandboxController::set_technique(const std::string& name) {
  return note(primary_->set_technique(name));
}

Status SandboxController::set_param(const std::string& name, const std::string& text) {
  // The session checks the key (naming the valid ones), the type and the range.
  return note(primary_->set_param(name + "=" + text));
}

Status SandboxController::set_param_value(const std::string& name, const graph::ParamValue& value) {
  return note(primary_->set_param(name, value));
}

Status SandboxController::reset_param(const std::string& name) {
  if (name == "all") {
    // Value by value, so uniform parameters never recompile; structural ones do (set_param).
    for (const graph::ParamDesc& d : primary_->params().descs())
      if (Status s = primary_->set_param(d.name, d.default_value); !s) return note(s);
    return note({});
  }
  const graph::ParamDesc* d = primary_->params().find(name);
  if (!d) return note(primary_->set_param(name + "="));
  return note(primary_->set_param(d->name, d->default_value));
}

Status SandboxController::save_preset(const std::string& path) const {
  return write_file_whole(path, technique::format_preset(primary_->technique(), primary_->params()));
}

std::vector<std::string> SandboxController::shipped_presets() const {
  const technique::Technique* technique = registry_.find(primary_->technique());
  return technique ? technique::shipped_presets(*technique) : std::vector<std::string>{};
}

Status SandboxController::load_preset(const std::string& name_or_path) {
  const technique::Technique* technique = registry_.find(primary_->technique());
  if (!technique) return note(make_error("no technique selected"));
  Result<technique::Preset> preset = technique::load_preset(*technique, name_or_path);
  if (!preset) return note(preset.error());
  // Validate against a copy first: nothing is applied unless everything fits.
  Result<graph::ParameterSet> next = technique::preset_applied(*preset, primary_->technique(), primary_->params());
  if (!next) {
    Error e = next.error();
    e.file = name_or_path;
    return note(e);
  }
  return note(primary_->apply_preset(preset->parameters_json));
}

// --- debug switches ---------------------------------------------------------------------------

Status SandboxController::set_no_reuse(bool on) {
  for (technique::TechniqueSession* s : sessions()) {
    s->compile_options().no_reuse = on;
    if (Status st = s->recompile(); !st) return note(st);
  }
  return note({});
}

Status SandboxController::set_extended_lifetimes(bool on) {
  for (technique::TechniqueSession* s : sessions()) {
    s->compile_options().extended_lifetimes = on;
    if (Status st = s->recompile(); !st) return note(st);
  }
  return note({});
}

void SandboxController::set_immediate(bool on) {
  for (technique::TechniqueSession* s : sessions()) s->executor().options().immediate = on;
}

// --- viewer and compare -----------------------------------------------------------------------

Status SandboxController::view_resource(const std::string& name) {
  const auto& resources = primary_->graph().resources;
  if (!name.empty() && std::none_of(resources.begin(), resources.end(),
                                    [&](const graph::ResourceDecl& r) { return r.name == name; })) {
    std::string known;
    for (const graph::ResourceDecl& r : resources)
      if (r.kind != graph::ResourceKind::imported) known += (known.empty() ? "" : ", ") + r.name;
    return note(make_error("technique '" + primary_->technique() + "' has no resource '" + shortened(name) +
                           "'; resources: " + known));
  }
  auto& keep = primary_->compile_options().keep_alive;
  if (name == viewer_.resource && (name.empty() || keep == std::vector<std::string>{name}))
    return note({});
  viewer_.resource = name;
  keep.clear();
  if (!name.empty()) keep.push_back(name);
  if (Status s = primary_->recompile(); !s) return note(s);
  // A useful first range: view distance for screen depth, [0, 1] for everything else.
  if (gl::Texture* t = primary_->executor().resource(name)) {
    // The z-buffer (linearised for display) and the contract's linear view depth: world units.
    bool screen_depth = (t->info().is_depth || name == technique::kViewDepth) && t->width() == width_ &&
                        t->height() == height_;
    viewer_.min = screen_depth ? camera().near_plane : 0.0f;
    viewer_.max = screen_depth && primary_->has_scene()
                      ? glm::length(camera().position - primary_->scene().bounds.center()) +
                            primary_->scene().bounds.radius()
                      : 1.0f;
  }
  return note({});
}

Status SandboxController::configure_secondary() {
  if (!secondary_) secondary_ = std::make_unique<technique::TechniqueSession>(registry_, library_);
  return configure_partner(*secondary_, *primary_, compare_.with, width_, height_);
}

std::vector<technique::TechniqueSession*> SandboxController::partners() const {
  std::vector<technique::TechniqueSession*> out;
  for (technique::TechniqueSession* s : {secondary_.get(), third_.get()})
    if (s) out.push_back(s);
  return out;
}

std::vector<technique::TechniqueSession*> SandboxController::sessions() const {
  std::vector<technique::TechniqueSession*> out = {primary_.get()};
  for (technique::TechniqueSession* s : partners()) out.push_back(s);
  return out;
}

std::vector<technique::TechniqueSession*> SandboxController::shown_sessions() {
  std::vector<technique::TechniqueSession*> out = {primary_.get()};
  if (compare_.enabled && secondary_) out.push_back(secondary_.get());
  if (compare_.enabled && compare_.three_way && third_) out.push_back(third_.get());
  return out;
}

Status SandboxController::set_three_way(bool on) {
  if (!on) {
    compare_.three_way = false;
    compare_.stats_b.reset();
    third_.reset();
    return note({});
  }
  if (!registry_.find(measurement::kReferenceTechnique))
    return note(make_error(std::string("three-way compare needs the '") + measurement::kReferenceTechnique +
                           "' technique, which is not registered"));
  if (!compare_.enabled)
    if (Status s = set_compare(true); !s) return s;
  if (!third_) third_ = std::make_unique<technique::TechniqueSession>(registry_, library_);
  if (Status s = configure_partner(*third_, *primary_, measurement::kReferenceTechnique, width_, height_); !s) {
    third_.reset();
    return note(s);
  }
  if (!compare_.three_way) {  // three equal columns to start
    compare_.split = 1.0f / 3.0f;
    compare_.split2 = 2.0f / 3.0f;
  }
  compare_.three_way = true;
  return note({});
}

Status SandboxController::set_compare(bool enabled, const std::string& with) {
  if (!enabled) {
    compare_.enabled = false;
    compare_.stats.reset();
    compare_.stats_b.reset();
    compare_.rmse_history.clear();
    compare_.three_way = false;
    secondary_.reset();  // frees its textures: compare mode costs nothing when off
    third_.reset();
    return note({});
  }
  std::string partner = with.empty() ? (compare_.with.empty() ? default_compare_partner(registry_, primary_->technique()) : compare_.with)
                                     : with;
  if (!registry_.find(partner)) return note(primary_->set_technique(partner));  // names valid ones
  std::string previous = compare_.with;
  compare_.with = partner;
  if (Status s = configure_secondary(); !s) {
    compare_.with = previous;
    if (!compare_.enabled) secondary_.reset();
    return note(s);
  }
  compare_.enabled = true;
  compare_.stats.reset();
  compare_.rmse_history.clear();
  return note({});
}

void SandboxController::update_compare_stats() {
  sandbox::update_compare_stats(compare_, *primary_, *secondary_, compare_.three_way ? third_.get() : nullptr);
}

// --- frames -----------------------------------------------------------------------------------

Status SandboxController::resize(int width, int height) {
  if (width == width_ && height == height_) return {};
  if (Status s = primary_->resize(width, height); !s) return note(s);
  for (technique::TechniqueSession* p : partners())
    if (Status s = p->resize(width, height); !s) return note(s);
  if (Status s = display_.resize(width, height); !s) return note(s);
  width_ = width;
  height_ = height;
  return {};
}

void SandboxController::reload_shaders() {
  for (technique::TechniqueSession* s : sessions()) s->shaders().reload_changed();
  display_.shaders().reload_changed();
}

std::vector<Error> SandboxController::shader_errors() const {
  std::vector<Error> all;
  for (technique::TechniqueSession* s : sessions())
    for (Error& e : s->shaders().errors()) all.push_back(std::move(e));
  for (Error& e : display_.shaders().errors()) all.push_back(std::move(e));
  return all;
}

Status SandboxController::start_sequence(const SequenceSpec& spec) {
  if (Status s = check_sequence(spec); !s) return note(s);
  if (!primary_->has_scene()) return note(make_error("no scene to record"));
  recording_ = Recording{spec, 0, camera(), light(), primary_->scene().bounds.center()};
  return note({});
}

void SandboxController::stop_sequence() { end_sequence(/*keep_frames=*/true); }

void SandboxController::end_sequence(bool keep_frames) {
  if (!recording_) return;
  camera() = recording_->camera;
  light() = recording_->light;
  Status kept = keep_frames ? recording_->frames->commit() : Status();
  recording_.reset();  // a batch not committed removes its frames
  if (!kept) (void)note(kept);
}

void SandboxController::pose_for_sequence() {
  const Recording& r = *recording_;
  const float degrees = r.spec.degrees * float(r.next) / float(r.spec.frames);
  if (r.spec.path == SequenceSpec::Path::orbit) camera() = orbited(r.camera, r.centre, degrees);
  else light() = turned(r.light, r.centre, degrees);
}

Status SandboxController::save_sequence_frame() {
  Recording& r = *recording_;
  const std::string path = sequence_frame_path(r.spec, r.next);
  Result<std::string> staged = r.frames->staged(path);
  Status saved = staged ? save_presentation_png(*staged) : Status(staged.error());
  if (!saved) {
    Error e = saved.error();
    e.file = path;
    e = r.frames->not_written(e);
    end_sequence(/*keep_frames=*/false);
    return e;
  }
  if (++r.next == r.spec.frames) {
    const std::string done = "recorded " + std::to_string(r.spec.frames) + " frames into " + r.spec.dir;
    Status committed = r.frames->commit();
    end_sequence(/*keep_frames=*/false);
    if (!committed) return committed;
    message_.clear();
    sequence_note_ = done;
  }
  return {};
}

Status SandboxController::render_frame() {
  if (recording_) pose_for_sequence();
  Status s = render_and_compose();
  if (s) {
    refused_.clear();
  } else {
    // Never leave the last good image up: the view shows that this frame was refused.
    refused_ = s.error().to_string();
    display_.show_refused();
  }
  // A refused frame is saved as refused: the sequence keeps its numbering.
  if (recording_)
    if (Status saved = save_sequence_frame(); !saved) return saved;
  return s;
}

Status SandboxController::render_and_compose() {
  auto now = std::chrono::steady_clock::now();
  if (now - last_reload_ > std::chrono::milliseconds(500)) {
    reload_shaders();
    if (reload_hook_) reload_hook_();
    last_reload_ = now;
  }
  if (Status s = primary_->render(); !s) return s;
  bool comparing = compare_.enabled && secondary_;
  if (comparing) {
    for (technique::TechniqueSession* p : partners()) {
      p->camera() = primary_->camera();
      p->light() = primary_->light();
      if (Status s = p->render(); !s) return s;
    }
    if (compare_.stats_every > 0 && frames_ % compare_.stats_every == 0) update_compare_stats();
  }
  ++frames_;

  if (frames_ % 15 == 1) refresh_viewed(*this);
  return compose_frame(display_, {*primary_, comparing ? secondary_.get() : nullptr,
                                  comparing && compare_.three_way ? third_.get() : nullptr, compare_, viewer_, width_,
                                  height_, debug_views_.texel_density});
}

Status SandboxController::rebuild_sessions(const std::function<Status()>& swap) {
  const technique::TechniqueSession& old = *primary_;
  const std::string technique = old.technique();
  const graph::ParameterSet params = old.params();
  const std::optional<scene::Scene> scene = old.has_scene() ? std::optional(old.scene()) : std::nullopt;
  const scene::Camera camera = primary_->camera();
  const scene::Light light = primary_->light();
  const graph::CompileOptions options = primary_->compile_options();
  const bool immediate = primary_->executor().options().immediate;
  const int shadow_size = old.settings().shadow_size;
  const scene::CascadeSettings cascades = old.cascades();
  secondary_.reset();
  third_.reset();
  primary_.reset();
  descriptions_.clear();
  const Status swapped = swap();

  primary_ = std::make_unique<technique::TechniqueSession>(registry_, library_);
  if (scene) primary_->set_scene(*scene);
  primary_->camera() = camera;
  primary_->light() = light;
  primary_->compile_options() = options;
  primary_->executor().options().immediate = immediate;
  if (Status s = primary_->resize(width_, height_); !s) return note(s);
  if (Status s = primary_->set_shadow_size(shadow_size); !s) return note(s);
  if (Status s = primary_->set_cascades(cascades); !s) return note(s);
  const bool still_there = registry_.find(technique) != nullptr;
  if (!still_there && registry_.names().empty())
    return note(make_error("no techniques are registered after the plugin reload", ErrorKind::internal));
  Status selected = primary_->set_technique(still_there ? technique : registry_.names().front());
  if (!selected) {  // the new build's graph does not compile: fall back to the first technique
    if (Status s = primary_->set_technique(registry_.names().front()); !s) return note(s);
  }
  if (selected && still_there)
    for (const graph::ParamDesc& d : params.descs())
      if (primary_->params().find(d.name)) (void)primary_->set_param(d.name, *params.get(d.name));  // may no longer fit
  if (!viewer_.resource.empty())
    if (Status s = view_resource(viewer_.resource); !s) (void)view_resource("");  // gone from the new graph
  if (compare_.enabled && (!registry_.find(compare_.with) || !configure_secondary())) compare_.enabled = false;
  if (compare_.three_way && (!compare_.enabled || !set_three_way(true))) compare_.three_way = false;
  if (!swapped) return note(swapped);
  return note(selected);
}

Status SandboxController::save_presentation_png(const std::string& path) const {
  return save_target_png(display_, path);
}

Status SandboxController::check_gl_errors(const std::string& when) {
  std::string codes;
  for (int i = 0; i < 32; ++i) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    codes += (codes.empty() ? "" : ", ") + std::string(gl::gl_error_name(e));
  }
  if (codes.empty()) return {};
  return make_error("GL error " + when + ": " + codes, ErrorKind::internal);
}

}  // namespace penumbra::sandbox
