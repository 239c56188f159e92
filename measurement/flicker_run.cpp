#include "measurement/flicker_run.h"

#include <algorithm>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "exec/gbuffer_readback.h"
#include "measurement/eval_capture.h"
#include "technique/frame_graph.h"

namespace penumbra::measurement {

namespace {

// Renders before each read: the first frame of a new camera or light must not show the previous one.
constexpr int kFramesPerStep = 2;

// Camera and light at step `t` of the motion, from where they started.
class Motion {
 public:
  Motion(technique::TechniqueSession& session, const FlickerSettings& settings)
      : session_(session), settings_(settings), camera_(session.camera()), light_(session.light()) {}
  ~Motion() {
    session_.camera() = camera_;
    session_.light() = light_;
  }
  void place(int t) {
    const float angle = glm::radians(settings_.degrees_per_frame * static_cast<float>(t));
    session_.camera() = camera_;
    session_.light() = light_;
    if (settings_.motion == "pan") {
      session_.camera().yaw += angle;
      return;
    }
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::vec3 centre = session_.scene().bounds.center();
    scene::Light& l = session_.light();
    l.direction = glm::normalize(glm::vec3(turn * glm::vec4(light_.direction, 0.0f)));
    l.position = centre + glm::vec3(turn * glm::vec4(light_.position - centre, 0.0f));
  }
  glm::mat4 view_proj() const {
    const graph::CompileSettings& s = session_.settings();
    return session_.camera().projection(static_cast<float>(s.screen_w) / static_cast<float>(s.screen_h)) *
           session_.camera().view();
  }

 private:
  technique::TechniqueSession& session_;
  FlickerSettings settings_;
  scene::Camera camera_;
  scene::Light light_;
};

Status keep_positions(technique::TechniqueSession& session) { return keep_alive(session, {"gbuffer_depth"}); }

Result<metrics::SurfaceFrame> read_frame(technique::TechniqueSession& session, const Motion& motion) {
  gl::Texture* mask = session.executor().resource(technique::kShadowMask);
  gl::Texture* depth = session.executor().resource("gbuffer_depth");
  if (!mask || !depth) return make_error("the frame lacks shadow_mask or gbuffer_depth", ErrorKind::internal);
  return metrics::SurfaceFrame{read_mask_image(*mask), exec::read_positions(*depth, session.camera(), exec::RowOrder::top_down), motion.view_proj()};
}

}  // namespace

Status check_flicker_motion(const std::string& motion) {
  if (motion == "pan" || motion == "light") return {};
  return make_error("--flicker expects pan or light, got '" + shortened(motion) + "'");
}

Result<float> pan_degrees_for_pixels(const scene::Camera& camera, int width, int height, float pixels) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::mat4 before = camera.projection(aspect) * camera.view();
  // Where the turned view's centre ray lands in the first view, pixels from its centre: it grows
  // with the angle until the ray leaves the view.
  auto centre_shift = [&](double radians) {
    scene::Camera turned = camera;
    turned.yaw += static_cast<float>(radians);
    const glm::vec4 clip = before * glm::vec4(turned.position + turned.forward(), 1.0f);
    return glm::length(0.5f * glm::vec2(clip) / clip.w * glm::vec2(width, height));
  };
  double lo = 0.0, hi = 0.5 * camera.fov_y;
  if (!(pixels > 0.0f) || centre_shift(hi) < pixels) {
    char m[160];
    std::snprintf(m, sizeof m, "--flicker-step %gpx turns the image centre out of the view in one frame", pixels);
    return make_error(m);
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (centre_shift(mid) < pixels ? lo : hi) = mid;
  }
  return static_cast<float>(glm::degrees(0.5 * (lo + hi)));
}

Result<FlickerSettings> resolved_flicker(technique::TechniqueSession& session, const FlickerSettings& flicker) {
  if (flicker.pixels_per_frame <= 0.0f) return flicker;
  if (flicker.motion != "pan") return make_error("a --flicker-step in pixels needs --flicker pan");
  const graph::CompileSettings& s = session.settings();
  auto degrees = pan_degrees_for_pixels(session.camera(), s.screen_w, s.screen_h, flicker.pixels_per_frame);
  if (!degrees) return degrees.error();
  FlickerSettings out = flicker;
  out.degrees_per_frame = *degrees;
  return out;
}

Result<std::vector<metrics::SurfaceFrame>> reference_motion_frames(technique::TechniqueSession& session,
                                                                   const ReferenceSettings& reference,
                                                                   const FlickerSettings& flicker) {
  Motion motion(session, flicker);
  std::vector<metrics::SurfaceFrame> frames;
  for (int t = 0; t < flicker.frames; ++t) {
    motion.place(t);
    auto ref = reference_frame(session, reference);
    if (!ref) return ref.error();
    // Positions come from this camera's G-buffer (a cached reference stores none); the cheapest
    // technique renders it: another reference frame would start a new accumulation.
    if (Status s = session.set_technique("hard"); !s) return s.error();
    if (Status s = keep_positions(session); !s) return s.error();
    if (Status s = session.render(); !s) return s.error();
    gl::Texture* depth = session.executor().resource("gbuffer_depth");
    if (!depth) return make_error("the reference frame lacks gbuffer_depth", ErrorKind::internal);
    frames.push_back({std::move(ref->mask), exec::read_positions(*depth, session.camera(), exec::RowOrder::top_down), motion.view_proj()});
  }
  return frames;
}

Result<std::vector<metrics::SurfaceFrame>> technique_motion_frames(technique::TechniqueSession& session,
                                                                   const TechniqueSpec& spec,
                                                                   const std::vector<std::string>& global_sets,
                                                                   const FlickerSettings& flicker) {
  if (Status s = select_technique(session, spec, global_sets); !s) return s.error();
  if (Status s = keep_positions(session); !s) return s.error();
  Motion motion(session, flicker);
  std::vector<metrics::SurfaceFrame> frames;
  for (int t = 0; t < flicker.frames; ++t) {
    motion.place(t);
    for (int f = 0; f < kFramesPerStep; ++f)
      if (Status s = session.render(); !s) return s.error();
    auto frame = read_frame(session, motion);
    if (!frame) return frame.error();
    frames.push_back(std::move(*frame));
  }
  return frames;
}

}  // namespace penumbra::measurement
