#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

#include "gl/context.h"

namespace penumbra::gl {
namespace {

std::string g_last_glfw_error;

void on_glfw_error(int code, const char* description) { g_last_glfw_error = description; }

class GlfwContext final : public Context {
 public:
  explicit GlfwContext(GLFWwindow* window) : window_(window) {}
  ~GlfwContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  ContextKind kind() const override { return ContextKind::glfw; }
  void make_current() override { glfwMakeContextCurrent(window_); }
  void swap_buffers() override { glfwSwapBuffers(window_); }
  GLFWwindow* window() override { return window_; }

 private:
  GLFWwindow* window_;
};

}  // namespace

Result<std::unique_ptr<Context>> create_glfw_context(const ContextOptions& options) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland)) {
    return make_error(
        "glfw: no display (DISPLAY and WAYLAND_DISPLAY are unset): run under a desktop or "
        "xvfb-run, or use --context egl or --context osmesa for headless work",
        ErrorKind::unavailable);
  }
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    return make_error("glfw: initialisation failed (" + g_last_glfw_error +
                          "): check the display, or use --context egl|osmesa",
                      ErrorKind::unavailable);
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug_output ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    return make_error("glfw: could not create a 4.5 core window (" + g_last_glfw_error + ")",
                      ErrorKind::unavailable);
  }
  auto ctx = std::make_unique<GlfwContext>(window);
  ctx->make_current();
  glfwSwapInterval(0);
  auto loader = [](const char* name) -> void* {
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
  };
  if (Status s = finish_context_setup(*ctx, options, "glfw", loader); !s) return s.error();
  return std::unique_ptr<Context>(std::move(ctx));
}

}  // namespace penumbra::gl
