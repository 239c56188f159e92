#include <GL/osmesa.h>

#include <vector>

#include "gl/context.h"
#include "gl/dynamic_library.h"

namespace penumbra::gl {
namespace {

// The few OSMesa entry points we use, resolved with dlsym (no link-time dependency).
struct OsMesaApi {
  DynamicLibrary lib{"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"};
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;

  bool load() {
    return lib.loaded() && lib.load(create_context_attribs, "OSMesaCreateContextAttribs") &&
           lib.load(make_current, "OSMesaMakeCurrent") &&
           lib.load(destroy_context, "OSMesaDestroyContext") &&
           lib.load(get_proc_address, "OSMesaGetProcAddress");
  }
};

OsMesaApi* g_api = nullptr;  // kept for the process: glad's pointers live in the library

class OsMesaContext final : public Context {
 public:
  OsMesaContext(OSMesaContext ctx, int w, int h)
      : ctx_(ctx), width_(w), height_(h), pixels_(static_cast<size_t>(w) * h * 4) {}
  ~OsMesaContext() override { g_api->destroy_context(ctx_); }
  ContextKind kind() const override { return ContextKind::osmesa; }
  void make_current() override {
    g_api->make_current(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, width_, height_);
  }

 private:
  OSMesaContext ctx_;
  int width_, height_;
  std::vector<unsigned char> pixels_;  // the default framebuffer; real work goes to FBOs
};

}  // namespace

Result<std::unique_ptr<Context>> create_osmesa_context(const ContextOptions& options) {
  if (!g_api) {
    auto api = std::make_unique<OsMesaApi>();
    if (!api->load()) {
      return make_error("osmesa: " +
                            (api->lib.loaded() ? std::string("libOSMesa lacks OSMesaCreateContextAttribs")
                                               : api->lib.error()) +
                            ": install libosmesa6 (scripts/setup.sh), or use --context egl",
                        ErrorKind::unavailable);
    }
    g_api = api.release();
  }
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                         OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
  OSMesaContext raw = g_api->create_context_attribs(attribs, nullptr);
  if (!raw) {
    return make_error("osmesa: could not create a 4.5 core-profile context (Mesa too old?)",
                      ErrorKind::unavailable);
  }
  auto ctx = std::make_unique<OsMesaContext>(raw, options.width, options.height);
  ctx->make_current();
  auto loader = [](const char* name) -> void* {
    return reinterpret_cast<void*>(g_api->get_proc_address(name));
  };
  if (Status s = finish_context_setup(*ctx, options, "osmesa", loader); !s) return s.error();
  return std::unique_ptr<Context>(std::move(ctx));
}

}  // namespace penumbra::gl
