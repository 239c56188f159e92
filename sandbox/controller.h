#pragma once
// SandboxController: the sandbox's state and every action on it. The ImGui panels and script
// steps call the SAME methods, so a script exercises exactly what a user clicks. It needs a
// current GL context but no window: the frame is composed into its own presentation texture
// (the window host blits it to the back buffer and draws the UI on top; a headless host reads it
// back), so soak tests run it under OSMesa.
//
//   SandboxController c(registry, library);
//   if (Status s = c.init("showcase", "pcss", 480, 320); !s) fail(s);
//   c.set_param("samples", "32");
//   c.set_compare(true);              // second session: "reference" if registered
//   c.render_frame();
//   c.save_presentation_png("out.png");
//
// Compare mode runs TWO TechniqueSessions (primary and secondary) over the same scene, camera
// and light: each keeps its own compiled plan, texture pool and timings, so both can be inspected
// and swapping one never recompiles the other. The cost is a second scene upload and a second
// G-buffer per frame, which only compare mode pays.
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sandbox/compare.h"
#include "sandbox/display.h"
#include "sandbox/frame_composer.h"
#include "sandbox/frame_sequence.h"
#include "exec/pass.h"
#include "metrics/mask_metrics.h"
#include "technique/technique.h"
#include "technique/technique_session.h"
#include "scene/staging.h"
#include "util/output_batch.h"

namespace penumbra::sandbox {


// The first view when no technique is asked for: a contact-hardening technique as good as PCSS
// (docs/results), so the first shadows are worth looking at; hard shadows are one click away.
inline constexpr const char* kStartTechnique = "sspcss";

class SandboxController {
 public:
  SandboxController(const technique::TechniqueRegistry& registry, const exec::PassLibrary& library);
  ~SandboxController();

  // Loads the scene, selects the technique (empty: kStartTechnique, else the first registered)
  // and sizes the frame.
  Status init(const std::string& scene, const std::string& technique, int width, int height);

  // --- scene, camera, light ---------------------------------------------------------------
  // A built-in name or a glTF path, staged (scene/staging.h) for the frame's aspect: a glTF model
  // gets a fitted camera, its own light or one that shows the shadows, and a ground plane when it
  // has no floor and the ground switch is on. A different scene than the current one drops the
  // camera pose and light overrides of the staging options (they were meant for the previous
  // one); the ground switch stays. On failure the previous scene stays.
  Status load_scene(const std::string& name_or_path);
  const std::string& scene_name() const { return scene_name_; }
  // The staging options the next load uses (the command line's --camera, --light-dir,
  // --light-size, --ground); set before init().
  void set_staging(const scene::StagingOptions& options) { staging_ = options; }
  const scene::StagingOptions& staging() const { return staging_; }
  // The ground switch: reloads the current scene with or without the added plane.
  Status set_ground(bool on);
  // Fitted camera, or one the glTF file places (Kind::file, by index or name): reloads and
  // restages the current scene with that camera.
  Status set_camera_choice(const scene::CameraChoice& choice);
  // Cameras the current glTF places (empty for built-in scenes).
  const std::vector<scene::SceneCamera>& file_cameras() const;
  bool ground_added() const;
  scene::Camera& camera() { return primary_->camera(); }
  scene::Light& light() { return primary_->light(); }
  // Free-fly camera: `axes` = (right, up, forward) in [-1, 1], dt in seconds; fast = Shift.
  void move_camera(const glm::vec3& axes, float dt, bool fast);
  // Mouse look, in pixels of mouse motion.
  void look(float dx, float dy);
  Status set_camera(const std::optional<glm::vec3>& position, const std::optional<glm::vec3>& look_at,
                    std::optional<float> yaw_deg, std::optional<float> pitch_deg);
  // Directional lights keep their emitter disk at the same distance from the scene centre.
  Status set_light_direction(glm::vec3 direction);
  Status set_light_type(scene::LightType type);
  Status set_light_size(float diameter);
  Status set_light_position(const glm::vec3& position);
  Status set_spot_angle(float radians);
  // Space in the window: the light looks where the camera looks (Sterna's demo).
  Status align_light_with_camera();
  // A frozen light (and so its shadow frustum, which is fitted to the scene, never to the camera)
  // stays put while the camera moves: every light change (Space, the gizmo, the Light panel, a
  // script's light step) is refused with a message until it is unfrozen.
  void set_light_frozen(bool frozen) { light_frozen_ = frozen; }
  bool light_frozen() const { return light_frozen_; }
  Status set_shadow_size(int texels);
  // Cascaded shadow maps (scene/cascades.h), in every session; a scene whose light is not
  // directional gets one cascade back (with a note), since its frames would be refused.
  Status set_cascades(const scene::CascadeSettings& cascades);

  // --- technique and parameters -------------------------------------------------------------
  std::vector<std::string> technique_names() const { return registry_.names(); }
  // The description in the technique's graph JSON (the one the CLI prints); read once per name.
  const std::string& technique_description(const std::string& name) const;
  Status set_technique(const std::string& name);
  technique::TechniqueSession& session() { return *primary_; }
  technique::TechniqueSession* secondary() { return secondary_.get(); }
  // Three-way compare's third session, running the reference (null otherwise).
  technique::TechniqueSession* reference_session() { return compare_.three_way ? third_.get() : nullptr; }
  // The sessions on screen, left to right: A; A, B; or A, B, reference.
  std::vector<technique::TechniqueSession*> shown_sessions();
  // `text` as on the command line ("32", "true", "vogel"); structural ones recompile.
  Status set_param(const std::string& name, const std::string& text);
  Status set_param_value(const std::string& name, const graph::ParamValue& value);
  Status reset_param(const std::string& name);  // "all" resets every parameter
  Status save_preset(const std::string& path) const;
  // A preset file, or the name of one the technique ships ("paper").
  Status load_preset(const std::string& name_or_path);
  // Names of the presets the current technique ships (technique/preset.h), sorted.
  std::vector<std::string> shipped_presets() const;

  // --- graph debug switches -----------------------------------------------------------------
  Status set_no_reuse(bool on);
  Status set_extended_lifetimes(bool on);
  void set_immediate(bool on);

  // --- resource viewer, compare -------------------------------------------------------------
  ViewerSettings& viewer() { return viewer_; }
  const DisplayPass& display() const { return display_; }
  // Keeps `name` alive in the primary plan (recompiles) and shows it; "" turns the viewer off.
  Status view_resource(const std::string& name);
  CompareState& compare() { return compare_; }
  // Shadow debug views (drawn by the window over the viewport; texel density by the composer).
  struct DebugViews {
    bool light_frustum = false;   // the shadow frustum and the emitter, in the scene
    bool blocker_region = false;  // the blocker-search cone/region of the pixel under the cursor
    bool texel_density = false;   // the frame shows shadow-map texels per pixel instead of colour
    bool light_gizmo = false;     // the sky disk in the viewport's corner: drag the light (light_gizmo.h)
  };
  DebugViews& debug_views() { return debug_views_; }
  // `with` empty: "reference" when registered, else the technique after the primary.
  Status set_compare(bool enabled, const std::string& with = "");
  void set_compare_view(CompareState::View view) { compare_.view = view; }
  // A | B | reference: a third session runs the reference technique (turns compare on; an error
  // when no "reference" is registered). Off frees it.
  Status set_three_way(bool on);
  // Reads the statistics back from the last rendered frame now (scripts' `metrics`, exports).
  void refresh_compare_stats() {
    if (compare_.enabled && secondary_ && frames_ > 0) update_compare_stats();
  }

  // --- frame sequences (sandbox/frame_sequence.h) -------------------------------------------
  // From the next frame on, each render_frame() poses the camera or light for frame i of the
  // sequence and saves the composed frame to sequence_frame_path(spec, i); after the last one
  // the pose the sequence started from is back. An error (and nothing recorded) for a bad spec.
  Status start_sequence(const SequenceSpec& spec);
  // Restores the starting pose; the frames saved so far are kept (a deliberate stop). A frame
  // that cannot be saved stops the sequence and keeps none of it: the frames appear together,
  // when the last is saved (util/output_batch.h).
  void stop_sequence();
  bool recording() const { return recording_.has_value(); }
  int sequence_saved() const { return recording_ ? recording_->next : 0; }
  int sequence_frames() const { return recording_ ? recording_->spec.frames : 0; }
  // "recorded N frames into DIR" once the last sequence finished; "" before.
  const std::string& sequence_note() const { return sequence_note_; }

  // --- frames -------------------------------------------------------------------------------
  Status resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  // Renders the session(s), updates compare statistics, composes the presentation texture and
  // (every ~0.5 s) reloads changed shaders.
  Status render_frame();
  std::uint64_t frames() const { return frames_; }
  // The error of the last frame when it was refused ("" after a good one). A refused frame's
  // presentation is DisplayPass::kRefusedColor, never the previous image.
  const std::string& refused() const { return refused_; }
  GLuint presentation_framebuffer() const { return display_.framebuffer(); }
  Status save_presentation_png(const std::string& path) const;
  // Shader compile errors of every program in use (technique passes and display), with file:line.
  std::vector<Error> shader_errors() const;
  void reload_shaders();
  // Drains glGetError; an error lists every code seen.
  static Status check_gl_errors(const std::string& when);

  // --- plugin reload (sandbox/plugin_reload.h) ----------------------------------------------
  // Destroys both sessions (their pass objects run plugin code), runs `swap` (which replaces
  // code in the registry and pass library this controller was made with), then builds them
  // again with the same scene, camera, light, sizes, debug switches and viewed resource, the
  // same technique when it still exists (else the first) and every parameter value that still
  // fits. The sessions come back whatever `swap` returns; its error is returned.
  Status rebuild_sessions(const std::function<Status()>& swap);
  // Runs from render_frame() every ~0.5 s, beside the shader reload (the plugin reloader's poll).
  void set_reload_hook(std::function<void()> hook) { reload_hook_ = std::move(hook); }

  // The last action's outcome for the UI: "" after success.
  const std::string& message() const { return message_; }
  Status note(Status s);  // records s in message() and returns it

 private:
  Status configure_secondary();
  Status render_and_compose();
  void update_compare_stats();
  void pose_for_sequence();
  Status light_change_allowed();  // an error (noted) when the light is frozen, saying how to unfreeze it
  std::vector<technique::TechniqueSession*> partners() const;  // secondary and third, those that exist
  std::vector<technique::TechniqueSession*> sessions() const;  // the primary, then partners()
  Status save_sequence_frame();

  struct Recording {
    SequenceSpec spec;
    int next = 0;  // the frame rendered next
    scene::Camera camera;  // the starting pose
    scene::Light light;
    glm::vec3 centre{0.0f};
    std::unique_ptr<OutputBatch> frames = std::make_unique<OutputBatch>();
  };
  void end_sequence(bool keep_frames);
  std::optional<Recording> recording_;
  bool light_frozen_ = false;
  std::string sequence_note_;  // "recorded N frames into DIR" after the last one

  const technique::TechniqueRegistry& registry_;
  mutable std::map<std::string, std::string> descriptions_;
  const exec::PassLibrary& library_;
  std::unique_ptr<technique::TechniqueSession> primary_;
  std::unique_ptr<technique::TechniqueSession> secondary_;
  std::unique_ptr<technique::TechniqueSession> third_;  // three-way compare: the reference
  std::string scene_name_;
  scene::StagingOptions staging_;
  DisplayPass display_;
  ViewerSettings viewer_;
  CompareState compare_;
  DebugViews debug_views_;
  int width_ = 0, height_ = 0;
  std::uint64_t frames_ = 0;
  std::string message_;
  std::string refused_;
  std::chrono::steady_clock::time_point last_reload_ = std::chrono::steady_clock::now();
  std::function<void()> reload_hook_;
};

}  // namespace penumbra::sandbox
