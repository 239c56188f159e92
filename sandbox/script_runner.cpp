#include "sandbox/script_runner.h"

#include "sandbox/viewed_resource.h"
#include "sandbox/compare_metrics.h"
#include "sandbox/graph_export.h"
#include "sandbox/inspector.h"

#include <cstdio>
#include <utility>

namespace penumbra::sandbox {

ScriptRunner::ScriptRunner(std::vector<ScriptStep> steps, ResizeFn resize)
    : steps_(std::move(steps)), resize_(std::move(resize)) {}

Status ScriptRunner::before_frame(SandboxController& c) {
  if (frames_left_ > 0) {
    --frames_left_;
    if (frames_left_ > 0) return {};
  }
  while (next_ < steps_.size()) {
    const ScriptStep& step = steps_[next_++];
    last_ = next_ - 1;
    if (Status s = run(step, c); !s) {
      Error e = step_error(step, s.error().to_string());
      e.kind = s.error().kind;
      e.details = s.error().details;
      return e;
    }
    if (step.kind == StepKind::wait) {
      frames_left_ = step.number;  // this frame is the first of them
      return {};
    }
    if (step.kind == StepKind::record) {
      frames_left_ = step.sequence.frames;  // one rendered and saved per frame
      return {};
    }
    if (step.kind == StepKind::screenshot) {
      screenshot_ = step.text;
      frames_left_ = 1;
      return {};
    }
  }
  return {};
}

Status ScriptRunner::run(const ScriptStep& step, SandboxController& c) {
  switch (step.kind) {
    case StepKind::scene: return c.load_scene(step.text);
    case StepKind::technique: return c.set_technique(step.text);
    case StepKind::set:
      for (const auto& [name, value] : step.assignments)
        if (Status s = c.set_param(name, value); !s) return s;
      return {};
    case StepKind::reset: return c.reset_param(step.text);
    case StepKind::ground: return c.set_ground(step.flag);
    case StepKind::metrics: return write_metrics(c, step.text);
    case StepKind::graph: return write_graph_view(c, step.text);
    case StepKind::record: return c.start_sequence(step.sequence);
    case StepKind::save_view: {
      Result<std::string> path = save_viewed_resource(c, step.text, *parse_view_format(step.format));
      return path ? Status{} : Status(path.error());
    }
    case StepKind::debug:
      if (step.light_frustum) c.debug_views().light_frustum = *step.light_frustum;
      if (step.light_gizmo) c.debug_views().light_gizmo = *step.light_gizmo;
      if (step.blocker_region) c.debug_views().blocker_region = *step.blocker_region;
      if (step.texel_density) c.debug_views().texel_density = *step.texel_density;
      return {};
    case StepKind::inspect: return write_inspection(c, step.inspect.x, step.inspect.y, step.inspect.out);
    case StepKind::camera:
      if (step.camera.choice) {
        scene::CameraChoice choice;
        choice.kind = *step.camera.choice == "fit" ? scene::CameraChoice::Kind::fitted : scene::CameraChoice::Kind::file;
        if (step.camera.choice->size() > 5) choice.file_camera = step.camera.choice->substr(5);
        return c.set_camera_choice(choice);
      }
      return c.set_camera(step.camera.position, step.camera.look_at, step.camera.yaw_deg,
                          step.camera.pitch_deg);
    case StepKind::light:
      if (step.light.frozen) c.set_light_frozen(*step.light.frozen);
      if (step.light.type)
        if (Status s = c.set_light_type(*step.light.type == "spot"    ? scene::LightType::spot
                                        : *step.light.type == "point" ? scene::LightType::point
                                                                      : scene::LightType::directional);
            !s)
          return s;
      if (step.light.position)
        if (Status s = c.set_light_position(*step.light.position); !s) return s;
      if (step.light.direction)
        if (Status s = c.set_light_direction(*step.light.direction); !s) return s;
      if (step.light.spot_angle_deg)
        if (Status s = c.set_spot_angle(glm::radians(*step.light.spot_angle_deg)); !s) return s;
      if (step.light.size) return c.set_light_size(*step.light.size);
      return {};
    case StepKind::shadow_size: return c.set_shadow_size(step.number);
    case StepKind::wait:
    case StepKind::screenshot: return {};
    case StepKind::compare:
      if (Status s = c.set_compare(step.compare.enabled, step.compare.with); !s) return s;
      if (step.compare.three_way)
        if (Status s = c.set_three_way(*step.compare.three_way && step.compare.enabled); !s) return s;
      if (step.compare.view == "split") c.set_compare_view(CompareState::View::split);
      if (step.compare.view == "error") c.set_compare_view(CompareState::View::error);
      if (step.compare.classes) c.compare().show_classes = *step.compare.classes;
      return {};
    case StepKind::view: {
      if (Status s = c.view_resource(step.view.resource); !s) return s;
      ViewerSettings& v = c.viewer();
      if (std::optional<int> map = colour_map_index(step.view.map)) v.map = static_cast<ViewerSettings::Map>(*map);
      if (step.view.placement == "full") v.placement = ViewerSettings::Placement::full;
      if (step.view.placement == "inset") v.placement = ViewerSettings::Placement::inset;
      if (step.view.channel_mask) v.channel_mask = *step.view.channel_mask;
      if (step.view.min) v.min = *step.view.min;
      if (step.view.max) v.max = *step.view.max;
      if (step.view.channel) v.channel = *step.view.channel;
      if (step.view.zoom) v.zoom.zoom = *step.view.zoom;
      if (step.view.center) v.zoom.center = *step.view.center;
      v.zoom = clamped(v.zoom);
      if (step.view.auto_range) {
        v.auto_range = *step.view.auto_range;
        if (v.auto_range) (void)apply_auto_range(c);  // again after the next frames
      }
      return {};
    }
    case StepKind::resize: return resize_(step.width, step.height);
    case StepKind::expect_no_gl_error: return SandboxController::check_gl_errors("before this step");
  }
  return {};
}

bool frame_refusal_is_fatal(const Error& e) { return e.kind == ErrorKind::internal; }

void report_refused_frame(const Error& e) {
  std::fprintf(stderr, "penumbra-sandbox: warning: frame refused (the sandbox keeps running): %s\n",
               e.to_string().c_str());
}

Status run_script_headless(SandboxController& controller, ScriptRunner& runner,
                           const std::function<Status()>& on_frame) {
  while (!runner.done()) {
    if (Status s = runner.before_frame(controller); !s) return s;
    if (runner.done()) break;  // the script ended without asking for another frame
    if (Status s = controller.render_frame(); !s) {
      Error e = runner.current() ? step_error(*runner.current(), "frame failed: " + s.error().to_string())
                                 : s.error();
      e.kind = s.error().kind;
      if (!frame_refusal_is_fatal(s.error())) {
        report_refused_frame(e);
      } else {
        return e;
      }
    }
    if (auto path = runner.take_screenshot())
      if (Status s = controller.save_presentation_png(*path); !s)
        return runner.current() ? step_error(*runner.current(), s.error().to_string()) : s.error();
    if (on_frame)
      if (Status s = on_frame(); !s) return s;
  }
  return {};
}

}  // namespace penumbra::sandbox
