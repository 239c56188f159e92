#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/dynamic_library.h"

namespace penumbra::gl {
namespace {

// EGL 1.5 core entry points through dlsym, extensions through eglGetProcAddress.
struct EglApi {
  DynamicLibrary lib{"libEGL.so.1", "libEGL.so"};
  PFNEGLGETPROCADDRESSPROC get_proc_address = nullptr;
  PFNEGLINITIALIZEPROC initialize = nullptr;
  PFNEGLTERMINATEPROC terminate = nullptr;
  PFNEGLBINDAPIPROC bind_api = nullptr;
  PFNEGLCHOOSECONFIGPROC choose_config = nullptr;
  PFNEGLCREATECONTEXTPROC create_context = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_context = nullptr;
  PFNEGLMAKECURRENTPROC make_current = nullptr;
  PFNEGLQUERYSTRINGPROC query_string = nullptr;
  PFNEGLGETERRORPROC get_error = nullptr;
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;

  bool load() {
    if (!lib.loaded() || !lib.load(get_proc_address, "eglGetProcAddress")) return false;
    bool ok = lib.load(initialize, "eglInitialize") && lib.load(terminate, "eglTerminate") &&
              lib.load(bind_api, "eglBindAPI") && lib.load(choose_config, "eglChooseConfig") &&
              lib.load(create_context, "eglCreateContext") &&
              lib.load(destroy_context, "eglDestroyContext") &&
              lib.load(make_current, "eglMakeCurrent") &&
              lib.load(query_string, "eglQueryString") && lib.load(get_error, "eglGetError");
    query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(get_proc_address("eglQueryDevicesEXT"));
    query_device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        get_proc_address("eglQueryDeviceStringEXT"));
    get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        get_proc_address("eglGetPlatformDisplayEXT"));
    return ok && get_platform_display;
  }
};

EglApi* g_api = nullptr;

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay dpy, EGLContext ctx) : dpy_(dpy), ctx_(ctx) {}
  ~EglContext() override {
    g_api->make_current(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    g_api->destroy_context(dpy_, ctx_);
    g_api->terminate(dpy_);
  }
  ContextKind kind() const override { return ContextKind::egl; }
  void make_current() override { g_api->make_current(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_); }

 private:
  EGLDisplay dpy_;
  EGLContext ctx_;
};

// A 4.5 core context with no surface on an initialised display, or nothing.
EGLContext create_core_context(EGLDisplay dpy) {
  EGLint major = 0, minor = 0;
  if (!g_api->initialize(dpy, &major, &minor)) return EGL_NO_CONTEXT;
  if (!g_api->bind_api(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  // No config is fine: EGL_KHR_no_config_context lets us pass EGL_NO_CONFIG_KHR.
  if (!g_api->choose_config(dpy, config_attribs, &config, 1, &count) || count == 0) config = nullptr;
  const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext ctx = g_api->create_context(dpy, config, EGL_NO_CONTEXT, ctx_attribs);
  if (ctx == EGL_NO_CONTEXT) g_api->terminate(dpy);
  return ctx;
}

struct Candidate {
  EGLDisplay display;
  std::string label;
};

// Hardware devices before software ones, then Mesa's surfaceless platform.
std::vector<Candidate> display_candidates() {
  std::vector<Candidate> hardware, software;
  if (g_api->query_devices) {
    EGLDeviceEXT devices[16];
    EGLint n = 0;
    if (g_api->query_devices(16, devices, &n)) {
      for (EGLint i = 0; i < n; ++i) {
        const char* ext = g_api->query_device_string
                              ? g_api->query_device_string(devices[i], EGL_EXTENSIONS)
                              : nullptr;
        bool is_software = ext && std::string(ext).find("EGL_MESA_device_software") != std::string::npos;
        EGLDisplay dpy = g_api->get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (dpy == EGL_NO_DISPLAY) continue;
        std::string label = "egl device " + std::to_string(i) + (is_software ? " (software)" : "");
        (is_software ? software : hardware).push_back({dpy, label});
      }
    }
  }
  EGLDisplay surfaceless =
      g_api->get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  std::vector<Candidate> all = hardware;
  all.insert(all.end(), software.begin(), software.end());
  if (surfaceless != EGL_NO_DISPLAY) all.push_back({surfaceless, "egl surfaceless"});
  return all;
}

}  // namespace

Result<std::unique_ptr<Context>> create_egl_context(const ContextOptions& options) {
  if (!g_api) {
    auto api = std::make_unique<EglApi>();
    if (!api->load()) {
      return make_error("egl: " +
                            (api->lib.loaded() ? std::string("libEGL lacks EGL 1.5 / platform entry points")
                                               : api->lib.error()) +
                            ": install libegl1 and a vendor (libegl-mesa0 or NVIDIA), or use "
                            "--context osmesa",
                        ErrorKind::unavailable);
    }
    g_api = api.release();
  }
  std::vector<Candidate> candidates = display_candidates();
  for (const Candidate& c : candidates) {
    EGLContext raw = create_core_context(c.display);
    if (raw == EGL_NO_CONTEXT) continue;
    auto ctx = std::make_unique<EglContext>(c.display, raw);
    ctx->make_current();
    auto loader = [](const char* name) -> void* {
      return reinterpret_cast<void*>(g_api->get_proc_address(name));
    };
    if (Status s = finish_context_setup(*ctx, options, c.label, loader); !s) {
      continue;  // e.g. a device that only offers an older GL: try the next one
    }
    return std::unique_ptr<Context>(std::move(ctx));
  }
  return make_error(candidates.empty()
                        ? "egl: no EGL device and no surfaceless platform found: use --context osmesa"
                        : "egl: no EGL display gave an OpenGL 4.5 core context (tried " +
                              std::to_string(candidates.size()) + "): use --context osmesa",
                    ErrorKind::unavailable);
}

}  // namespace penumbra::gl
