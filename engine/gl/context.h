#pragma once
// One GL 4.5 core context behind one interface, whatever created it:
//   glfw   - a window (the sandbox), needs a display;
//   osmesa - llvmpipe on the CPU (tests, CI), libOSMesa loaded at run time;
//   egl    - headless: EGL device platform first (an NVIDIA GPU on a server), then Mesa's
//            surfaceless platform; libEGL loaded at run time.
// Every backend loads GL through the same glad loader, so code above this line never asks
// which one it runs on.
//
//   auto ctx = gl::create_context({.kind = gl::parse_context_kind("osmesa").value()});
//   if (!ctx) { fmt::print(stderr, "{}\n", ctx.error().to_string()); return ctx.error().exit_code(); }
//   gl::ContextInfo info = (*ctx)->info();
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "util/error.h"

struct GLFWwindow;

namespace penumbra::gl {

enum class ContextKind { glfw, osmesa, egl };

std::string_view to_string(ContextKind kind);
// Accepts "glfw", "osmesa", "egl"; an error lists the valid names.
Result<ContextKind> parse_context_kind(std::string_view name);

struct ContextOptions {
  // Empty: PENUMBRA_CONTEXT, else egl then osmesa (headless) or glfw (window).
  std::optional<ContextKind> kind;
  bool want_window = false;  // chooses the default backend: glfw when true
  int width = 1280;          // window size / default framebuffer size
  int height = 720;
  std::string title = "Penumbra";
  bool visible = true;       // glfw only
  bool debug_output = true;  // KHR_debug messages to spdlog
};

struct ContextInfo {
  std::string backend;  // "osmesa", "egl (device 0: NVIDIA)", ...
  std::string version, renderer, vendor, glsl_version;
  int major = 0, minor = 0;
  int max_texture_size = 0;
  int max_compute_work_group_count[3] = {0, 0, 0};
  int max_compute_work_group_size[3] = {0, 0, 0};
  int max_compute_work_group_invocations = 0;
  int max_compute_shared_memory = 0;
  int max_image_units = 0;
  int max_texture_units = 0;
  bool software = false;  // llvmpipe/softpipe: timer queries do not measure the work
};

class Context {
 public:
  virtual ~Context() = default;
  virtual ContextKind kind() const = 0;
  virtual void make_current() = 0;
  // Window backends present the default framebuffer; headless ones do nothing.
  virtual void swap_buffers() {}
  virtual GLFWwindow* window() { return nullptr; }
  // Queried once after glad loaded the entry points.
  const ContextInfo& info() const { return info_; }

 protected:
  ContextInfo info_;
  friend Status finish_context_setup(Context&, const ContextOptions&, const std::string&,
                                     void* (*)(const char*));
};

// Creates the context, makes it current and loads GL. Failures are values with a message
// naming what is missing and what to try (exit code 2 in the CLI).
Result<std::unique_ptr<Context>> create_context(const ContextOptions& options);

// The current context renders in software (llvmpipe, softpipe): GL timer queries do not measure
// its work, and sizes meant for a GPU take minutes there.
bool current_context_is_software();

// Backends (context_glfw.cpp, context_osmesa.cpp, context_egl.cpp).
Result<std::unique_ptr<Context>> create_glfw_context(const ContextOptions& options);
Result<std::unique_ptr<Context>> create_osmesa_context(const ContextOptions& options);
Result<std::unique_ptr<Context>> create_egl_context(const ContextOptions& options);

// Shared tail of every backend: glad load, version check (4.5 core), debug output, info query.
using ProcLoader = void* (*)(const char*);
Status finish_context_setup(Context& ctx, const ContextOptions& options, const std::string& backend,
                            ProcLoader loader);

}  // namespace penumbra::gl
