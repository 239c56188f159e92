#pragma once
// The real sandbox window driven with real input: an X server of its own (Xvfb, display picked
// by the server), the sandbox in it writing its state every frame (--state-file), and xdotool
// sending X events through XTEST, as a user's mouse and keyboard would. Tests read the state
// (where widgets are, what is open, parameter values) and screenshots (F12).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "xvfb_run.h"

namespace penumbra::sandbox_test {

class LiveSandbox {
 public:
  // `args`: the sandbox's command line after the binary (--state-file is added). Throws when
  // Xvfb, xdotool or the window does not come up, with the sandbox's output.
  LiveSandbox(const std::string& binary, const std::string& args, const std::filesystem::path& dir) : dir_(dir) {
    namespace fs = std::filesystem;
    fs::create_directories(dir_);
    if (run("command -v Xvfb && command -v xdotool").exit_code != 0)
      throw std::runtime_error("Xvfb or xdotool is not installed: run scripts/setup.sh");
    const fs::path display_file = dir_ / "display";
    xvfb_pid_ = background("xvfb", "exec Xvfb -displayfd 3 -screen 0 1600x1200x24 -nolisten tcp 3>" + q(display_file));
    for (int i = 0; i < 200 && display_.empty(); ++i) {
      std::ifstream in(display_file);
      std::string line;
      if (std::getline(in, line) && !line.empty() && in.good()) display_ = ":" + line;
      else std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (display_.empty()) throw std::runtime_error("Xvfb did not start");
    state_file_ = (dir_ / "state.json").string();
    sandbox_pid_ = background("sandbox", "cd " + q(dir_) + " && DISPLAY=" + display_ + " XDG_CONFIG_HOME=" +
                                             q(dir_ / "config") + " exec " + binary + " " + args + " --state-file " +
                                             q(state_file_) + " >" + q(dir_ / "sandbox.log") + " 2>&1");
    state_ = wait_for([](const nlohmann::json& s) { return s.value("frame", 0) >= 3; }, 60.0, "the first frames");
    window_ = xdo("search --name \"Penumbra sandbox\"");
    window_ = window_.substr(0, window_.find('\n'));
    if (window_.empty()) throw std::runtime_error("no sandbox window: " + log());
  }
  ~LiveSandbox() {
    for (pid_t pid : {sandbox_pid_, xvfb_pid_})
      if (pid > 0) {
        ::kill(pid, SIGTERM);
        for (int i = 0; i < 100 && ::kill(pid, 0) == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
        ::kill(pid, SIGKILL);
      }
  }
  LiveSandbox(const LiveSandbox&) = delete;
  LiveSandbox& operator=(const LiveSandbox&) = delete;

  // xdotool with this display; returns its output.
  std::string xdo(const std::string& args) {
    RunResult r = run("DISPLAY=" + display_ + " xdotool " + args);
    if (r.exit_code != 0) throw std::runtime_error("xdotool " + args + ": " + r.output);
    return r.output;
  }
  // The state once `frames` more frames are drawn after the newest one written now (input sent
  // before is handled by then when frames >= 2: the next frame may have polled its events just
  // before the input arrived). Counting from the last state read instead raced: under load the
  // sandbox is often frames ahead of it, and the wait ended before the input was handled.
  nlohmann::json settle(int frames = 4) {
    read_state();
    const int from = state_.value("frame", 0);
    return wait_for([&](const nlohmann::json& s) { return s.value("frame", 0) >= from + frames; }, 60.0,
                    std::to_string(frames) + " more frames");
  }
  nlohmann::json state() const { return state_; }

  // Window pixel of a probed widget's centre; throws when the state has no such widget.
  std::pair<int, int> centre(const std::string& item) const {
    if (!state_["items"].contains(item)) throw std::runtime_error("no widget '" + item + "' in " + state_["items"].dump());
    const auto& r = state_["items"][item];
    return {int(r[0].get<float>() + r[2].get<float>() / 2), int(r[1].get<float>() + r[3].get<float>() / 2)};
  }
  void move_to(int x, int y) { xdo("mousemove --window " + window_ + " " + std::to_string(x) + " " + std::to_string(y)); }
  void click_at(int x, int y) {
    move_to(x, y);
    settle(2);  // ImGui hovers on one frame and takes the click on the next
    xdo("click 1");
  }
  // Presses the left button at (x0, y0), moves to (x1, y1) in `steps` steps a frame or more
  // apart (ImGui drags by the motion it sees each frame), and releases it there.
  void drag(int x0, int y0, int x1, int y1, int steps = 2) {
    move_to(x0, y0);
    settle(2);
    xdo("mousedown 1");
    settle(2);
    for (int i = 1; i <= steps; ++i) {
      move_to(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps);
      settle(2);
    }
    xdo("mouseup 1");
  }
  // Scrolls the panel until the widget is inside the window, then clicks its centre.
  void click(const std::string& item) {
    scroll_into_view(item);
    auto [x, y] = centre(item);
    click_at(x, y);
  }
  // Clicks a text field and waits until ImGui has made it the active widget, so keys sent next
  // reach it (a Ctrl+A sent before that selects nothing, and typing appends to the old text).
  void focus(const std::string& item) {
    click(item);
    for (int i = 0; i < 30; ++i)
      if (settle(1).value("active", "") == item) return;
    throw std::runtime_error("'" + item + "' did not become active after a click; active: " +
                             state_.value("active", std::string()));
  }
  // Focuses a text field and deletes its `chars` characters with End and BackSpace: single keys,
  // where a Ctrl+A chord was seen to select nothing in about one run in six under Xvfb (the typed
  // text then followed the old one).
  void clear_field(const std::string& item, size_t chars) {
    focus(item);
    std::string keys = "key End";
    for (size_t i = 0; i < chars; ++i) keys += " BackSpace";
    xdo(keys);
  }
  // Whether `done(state)` holds within `frames` frames.
  template <class Done>
  bool within(int frames, Done done) {
    for (int i = 0; i < frames; ++i)
      if (done(settle(1))) return true;
    return false;
  }
  // Whether the widget shows up within `frames` frames (a list's entries appear once it is drawn).
  bool wait_for_item(const std::string& item, int frames = 20) {
    for (int i = 0; i < frames; ++i)
      if (settle(1)["items"].contains(item)) return true;
    return false;
  }
  // Waits until the widget sits still for two frames (a list just opened moves once ImGui has
  // measured it).
  void wait_still(const std::string& item) {
    nlohmann::json last;
    for (int i = 0; i < 20; ++i) {
      nlohmann::json now = settle(1)["items"].value(item, nlohmann::json());
      if (!now.is_null() && now == last) return;
      last = std::move(now);
    }
  }
  void scroll_into_view(const std::string& item) {
    wait_still(item);
    for (int i = 0; i < 40; ++i) {
      const auto& r = state_["items"][item];
      const float top = r[1].get<float>(), bottom = top + r[3].get<float>();
      const int h = state_["window"][1].get<int>();
      if (top >= 0.0f && bottom <= float(h)) return;
      move_to(state_["panel"][2].get<int>() / 2, h / 2);
      xdo(std::string("click ") + (bottom > float(h) ? "5" : "4"));  // wheel down / up
      settle(3);
    }
    throw std::runtime_error("cannot scroll '" + item + "' into view");
  }
  void key(const std::string& keys) { xdo("key --clearmodifiers " + keys); }
  // F12 over the viewport: the sandbox saves its window into the test folder.
  std::filesystem::path screenshot() {
    const auto& vp = state_["viewport"];
    move_to(vp[0].get<int>() + vp[2].get<int>() - 5, vp[1].get<int>() + 5);
    settle(2);
    const auto shot = dir_ / "penumbra-screenshot.png";
    std::filesystem::remove(shot);
    key("F12");
    wait_for([&](const nlohmann::json&) { return std::filesystem::exists(shot); }, 30.0, "the screenshot");
    return shot;
  }
  std::string log() const {
    std::ifstream in(dir_ / "sandbox.log");
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  const std::string& window() const { return window_; }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  static std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }
  // Starts `command` (a shell line ending in exec, so the pid is the program's) in the
  // background, its output away from our pipe, and returns its pid.
  pid_t background(const std::string& name, const std::string& command) {
    const std::filesystem::path script = dir_ / (name + ".sh");
    std::ofstream(script) << command << "\n";
    RunResult r = run("sh " + q(script) + " </dev/null >/dev/null 2>&1 & echo $!");
    return static_cast<pid_t>(std::atoi(r.output.c_str()));
  }
  // The newest complete state the sandbox has written (a half-written file is skipped).
  void read_state() {
    std::ifstream in(state_file_);
    if (!in) return;
    nlohmann::json s = nlohmann::json::parse(in, nullptr, false);
    if (!s.is_discarded()) state_ = std::move(s);
  }
  template <class Done>
  const nlohmann::json& wait_for(Done done, double seconds, const std::string& what) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
      read_state();
      if (!state_.is_null() && done(state_)) return state_;
      if (sandbox_pid_ > 0 && ::kill(sandbox_pid_, 0) != 0) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(30));
    }
    throw std::runtime_error("waiting for " + what + ": timed out or the sandbox ended; its output:\n" + log());
  }

  std::filesystem::path dir_;
  std::string display_, state_file_, window_;
  pid_t xvfb_pid_ = -1, sandbox_pid_ = -1;
  nlohmann::json state_;
};

}  // namespace penumbra::sandbox_test
