#include "sandbox/window_host.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "sandbox/input_queue.h"
#include "sandbox/layout.h"
#include "sandbox/script_runner.h"
#include "sandbox/ui_panels.h"
#include "sandbox/ui_state_dump.h"
#include "util/png.h"
#include "util/row_order.h"

namespace penumbra::sandbox {

namespace {

// The back buffer as the user sees it (scene + UI), first row at the top.
Status save_back_buffer(const std::string& path, int width, int height) {
  std::vector<unsigned char> bottom_up(static_cast<size_t>(width) * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  std::vector<unsigned char> top_down = rows_flipped(bottom_up, static_cast<size_t>(width) * 4, height);
  for (size_t i = 3; i < top_down.size(); i += 4) top_down[i] = 255;  // the window is opaque
  return write_png_rgba8(path, width, height, top_down);
}

static_assert(InputEvent::kPress == GLFW_PRESS && InputEvent::kRelease == GLFW_RELEASE &&
              InputEvent::kRepeat == GLFW_REPEAT);

// Key and character events reach ImGui through the queue (sandbox/input_queue.h): ImGui 1.86's
// own callbacks set key state directly, so a tap between two frames was never seen down.
InputQueue* g_input = nullptr;
void queue_key(GLFWwindow*, int key, int scancode, int action, int mods) {
  if (g_input) g_input->push({.kind = InputEvent::Kind::key, .key = key, .scancode = scancode, .action = action, .mods = mods});
}
void queue_char(GLFWwindow*, unsigned codepoint) {
  if (g_input) g_input->push({.kind = InputEvent::Kind::character, .codepoint = codepoint});
}
void deliver_to_imgui(GLFWwindow* w, const std::vector<InputEvent>& events) {
  for (const InputEvent& e : events) {
    if (e.kind == InputEvent::Kind::key) ImGui_ImplGlfw_KeyCallback(w, e.key, e.scancode, e.action, e.mods);
    else ImGui_ImplGlfw_CharCallback(w, e.codepoint);
  }
}

// WASD + right-mouse look + Shift (held keys, polled); Space aligns the light and F12 asks for
// a screenshot (taps, from this frame's events).
class CameraInput {
 public:
  void update(GLFWwindow* w, SandboxController& c, UiState& ui, const Rect& viewport, float dt,
              const std::vector<InputEvent>& events) {
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureKeyboard) {
      auto down = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS; };
      glm::vec3 axes(float(down(GLFW_KEY_D)) - float(down(GLFW_KEY_A)),
                     float(down(GLFW_KEY_E)) - float(down(GLFW_KEY_Q)),
                     float(down(GLFW_KEY_W)) - float(down(GLFW_KEY_S)));
      if (axes != glm::vec3(0.0f))
        c.move_camera(axes, dt, down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT));
      if (pressed_in(events, GLFW_KEY_SPACE)) {
        (void)c.align_light_with_camera();  // refused with a message when the light is frozen
        ui.probe.keys["space"]++;
      }
      if (pressed_in(events, GLFW_KEY_F12)) {
        ui.screenshot_requested = true;
        ui.probe.keys["f12"]++;
      }
    }
    ui.escape = pressed_in(events, GLFW_KEY_ESCAPE);
    double x = 0, y = 0;
    glfwGetCursorPos(w, &x, &y);
    bool rmb = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (rmb && !looking_ && !io.WantCaptureMouse && viewport.contains(int(x), int(y))) looking_ = true;
    if (!rmb) looking_ = false;
    if (looking_) c.look(float(x - last_x_), float(y - last_y_));
    // Zoom (wheel, about the cursor) and pan (middle drag) of what fills the frame.
    const bool over = viewport.contains(int(x), int(y)) && !io.WantCaptureMouse;
    const glm::vec2 frame(float(std::max(c.width(), 1)), float(std::max(c.height(), 1)));
    ViewZoom& zoom = c.viewer().zoom;
    if (over && io.MouseWheel != 0.0f) {
      const glm::vec2 anchor((float(x) - viewport.x) / frame.x, 1.0f - (float(y) - viewport.y) / frame.y);
      zoom = zoom_about(zoom, std::pow(1.25f, io.MouseWheel), anchor);
    }
    const bool mmb = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    if (mmb && !panning_ && over) panning_ = true;
    if (!mmb) panning_ = false;
    if (panning_) zoom = pan_by(zoom, glm::vec2(float(x - last_x_) / frame.x, -float(y - last_y_) / frame.y));
    last_x_ = x;
    last_y_ = y;
  }

 private:
  bool looking_ = false, panning_ = false;
  double last_x_ = 0, last_y_ = 0;
};

}  // namespace

int run_window(gl::Context& context, SandboxController& controller, const WindowRun& run) {
  GLFWwindow* window = context.window();
  const bool scripted = run.script.has_value() || !run.final_screenshot.empty();
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  if (scripted) io.IniFilename = nullptr;  // reproducible layout for scripted screenshots
  ImGui::StyleColorsDark();
  // Opaque lists and tooltips: the frame behind them must not show through.
  ImGui::GetStyle().Colors[ImGuiCol_PopupBg].w = 1.0f;
  ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 1.0f;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  InputQueue input_queue;
  g_input = &input_queue;
  glfwSetKeyCallback(window, queue_key);  // after ImGui's: these replace its key and char callbacks
  glfwSetCharCallback(window, queue_char);
  ImGui_ImplOpenGL3_Init("#version 450");

  UiState ui;
  // The script's and --size's sizes are the FRAME's: the window is as much wider as the panel.
  std::optional<ScriptRunner> runner;
  if (run.script)
    runner.emplace(*run.script, [&](int w, int h) -> Status {
      glfwSetWindowSize(window, window_width_for(w, ui.panel_width), h);
      return controller.resize(w, h);
    });

  CameraInput input;
  int exit_code = 0;
  bool final_shot_taken = run.final_screenshot.empty();
  double last_time = glfwGetTime();
  std::uint64_t frame = 0;
  while (!glfwWindowShouldClose(window)) {
    glfwPollEvents();
    const std::vector<InputEvent> events = input_queue.take_frame();
    deliver_to_imgui(window, events);
    double now = glfwGetTime();
    float dt = static_cast<float>(now - last_time);
    last_time = now;
    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window, &fb_w, &fb_h);
    const Layout layout = compute_layout(fb_w, fb_h, ui.panel_width);
    ui.panel_width = layout.panel_width;
    // Interactive: the frame follows the viewport (so its aspect is the viewport's). Scripted: the
    // script's size is authoritative (a window manager may not honour a resize at once).
    if (!scripted && layout.viewport.w > 0 && layout.viewport.h > 0)
      (void)controller.resize(layout.viewport.w, layout.viewport.h);

    // ImGui needs two frames to lay out its windows before a screenshot shows them.
    bool script_finished = !runner;
    if (runner && frame >= 2) {
      if (Status s = runner->before_frame(controller); !s) {
        std::fprintf(stderr, "penumbra-sandbox: %s\n", s.error().to_string().c_str());
        exit_code = s.error().exit_code();
        break;
      }
      script_finished = runner->done();
    } else if (runner) {
      script_finished = false;
    }
    bool take_final = false;
    if (scripted && script_finished) {
      if (final_shot_taken) break;
      take_final = frame >= 2;
    }

    input.update(window, controller, ui, layout.viewport, dt, events);
    if (Status s = controller.render_frame(); !s) {
      const ScriptStep* step = runner ? runner->current() : nullptr;
      Error e = step ? step_error(*step, "frame failed: " + s.error().to_string()) : s.error();
      e.kind = s.error().kind;
      if (scripted && frame_refusal_is_fatal(e)) {
        std::fprintf(stderr, "penumbra-sandbox: %s\n", e.to_string().c_str());
        exit_code = 1;
        break;
      }
      if (scripted) report_refused_frame(e);
      (void)controller.note(s);  // shown in the UI; the sandbox keeps running
    }
    const int w = controller.width(), h = controller.height();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, std::max(fb_w, 1), std::max(fb_h, 1));
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // The frame at the viewport's top-left, 1:1 (never stretched, never under the panel).
    const int dst_x = layout.viewport.x, dst_top = fb_h - layout.viewport.y;
    glBlitNamedFramebuffer(controller.presentation_framebuffer(), 0, 0, 0, w, h, dst_x, dst_top - h, dst_x + w,
                           dst_top, GL_COLOR_BUFFER_BIT, GL_NEAREST);

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    draw_sandbox_ui(controller, ui, layout);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    std::vector<std::string> shots;
    if (runner)
      if (auto p = runner->take_screenshot()) shots.push_back(*p);
    if (ui.screenshot_requested) {
      shots.push_back(ui.screenshot_path);
      ui.screenshot_requested = false;
    }
    if (take_final) {
      shots.push_back(run.final_screenshot);
      final_shot_taken = true;
    }
    for (const std::string& path : shots) {
      Status s = save_back_buffer(path, fb_w, fb_h);
      if (s) ui.post("saved " + path, ImGui::GetTime());
      else (void)controller.note(s);
      if (!s && scripted) {
        std::fprintf(stderr, "penumbra-sandbox: %s\n", s.error().to_string().c_str());
        exit_code = s.error().exit_code();
      }
    }
    if (!run.state_file.empty())
      if (Status s = write_ui_state(run.state_file, controller, ui, layout, frame, fb_w, fb_h); !s) {
        std::fprintf(stderr, "penumbra-sandbox: %s\n", s.error().to_string().c_str());
        exit_code = s.error().exit_code();
      }
    context.swap_buffers();
    ++frame;
    if (exit_code != 0) break;
    if (run.max_fps > 0) {  // --max-fps: sleep out the rest of the frame's time
      const double until = now + 1.0 / run.max_fps;
      if (const double left = until - glfwGetTime(); left > 0)
        std::this_thread::sleep_for(std::chrono::duration<double>(left));
    }
  }
  g_input = nullptr;
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return exit_code;
}

}  // namespace penumbra::sandbox
