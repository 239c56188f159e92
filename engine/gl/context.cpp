#include "gl/context.h"

#include <glad/gl.h>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <cstring>

#include "gl/debug_output.h"

namespace penumbra::gl {

std::string_view to_string(ContextKind kind) {
  switch (kind) {
    case ContextKind::glfw: return "glfw";
    case ContextKind::osmesa: return "osmesa";
    case ContextKind::egl: return "egl";
  }
  return "?";
}

Result<ContextKind> parse_context_kind(std::string_view name) {
  if (name == "glfw") return ContextKind::glfw;
  if (name == "osmesa") return ContextKind::osmesa;
  if (name == "egl") return ContextKind::egl;
  return make_error("unknown context '" + std::string(name) + "': expected glfw, osmesa or egl");
}

static int get_int(GLenum e) {
  GLint v = 0;
  glGetIntegerv(e, &v);
  return v;
}

static std::string get_string(GLenum e) {
  const auto* s = reinterpret_cast<const char*>(glGetString(e));
  return s ? s : "";
}

Status finish_context_setup(Context& ctx, const ContextOptions& options, const std::string& backend,
                            ProcLoader loader) {
  int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(loader));
  if (version == 0) {
    return make_error(backend + ": glad could not load the GL entry points", ErrorKind::unavailable);
  }
  ContextInfo& info = ctx.info_;
  info.backend = backend;
  info.major = GLAD_VERSION_MAJOR(version);
  info.minor = GLAD_VERSION_MINOR(version);
  if (info.major * 10 + info.minor < 45) {
    return make_error(backend + ": got OpenGL " + std::to_string(info.major) + "." +
                          std::to_string(info.minor) + ", Penumbra needs 4.5 core",
                      ErrorKind::unavailable);
  }
  info.version = get_string(GL_VERSION);
  info.renderer = get_string(GL_RENDERER);
  info.vendor = get_string(GL_VENDOR);
  info.glsl_version = get_string(GL_SHADING_LANGUAGE_VERSION);
  info.max_texture_size = get_int(GL_MAX_TEXTURE_SIZE);
  for (GLuint i = 0; i < 3; ++i) {
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &info.max_compute_work_group_count[i]);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, i, &info.max_compute_work_group_size[i]);
  }
  info.max_compute_work_group_invocations = get_int(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS);
  info.max_compute_shared_memory = get_int(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE);
  info.max_image_units = get_int(GL_MAX_IMAGE_UNITS);
  info.max_texture_units = get_int(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS);
  info.software = info.renderer.find("llvmpipe") != std::string::npos ||
                  info.renderer.find("softpipe") != std::string::npos;
  if (options.debug_output) install_debug_output();
  spdlog::debug("{}: {} / {}", backend, info.version, info.renderer);
  return {};
}

Result<std::unique_ptr<Context>> create_context(const ContextOptions& options) {
  std::optional<ContextKind> kind = options.kind;
  if (!kind) {
    if (const char* env = std::getenv("PENUMBRA_CONTEXT"); env && *env) {
      auto parsed = parse_context_kind(env);
      if (!parsed) {
        Error e = parsed.error();
        e.where = "PENUMBRA_CONTEXT";
        return e;
      }
      kind = *parsed;
    }
  }
  if (kind) {
    switch (*kind) {
      case ContextKind::glfw: return create_glfw_context(options);
      case ContextKind::osmesa: return create_osmesa_context(options);
      case ContextKind::egl: return create_egl_context(options);
    }
  }
  if (options.want_window) return create_glfw_context(options);
  // Headless default: a GPU through EGL if there is one, else llvmpipe through OSMesa.
  auto egl = create_egl_context(options);
  if (egl) return egl;
  spdlog::debug("egl unavailable ({}), falling back to osmesa", egl.error().message);
  auto osmesa = create_osmesa_context(options);
  if (osmesa) return osmesa;
  return make_error("no headless GL context: egl: " + egl.error().message +
                        "; osmesa: " + osmesa.error().message,
                    ErrorKind::unavailable);
}

bool current_context_is_software() {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && (std::strstr(renderer, "llvmpipe") != nullptr || std::strstr(renderer, "softpipe") != nullptr);
}

}  // namespace penumbra::gl
