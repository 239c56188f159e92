#include "gl/debug_output.h"

#include <execinfo.h>
#include <glad/gl.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>

namespace penumbra::gl {
namespace {

const char* type_name(GLenum type) {
  switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    default: return "other";
  }
}

void GLAD_API_PTR on_debug_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                   GLsizei length, const GLchar* message, const void* user) {
  // Compile errors reach the caller as Error values with file and line; don't log them twice.
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION || source == GL_DEBUG_SOURCE_SHADER_COMPILER) {
    spdlog::trace("GL: {}", message);
  } else if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH) {
    spdlog::error("GL {}: {}", type_name(type), message);
  } else {
    spdlog::debug("GL {}: {}", type_name(type), message);
  }
}

#ifdef PENUMBRA_GL_STRICT
// glad's debug loader calls this after every GL function. glGetError itself goes through
// glad_glGetError, the raw pointer, so this does not recurse.
void post_call_check(void* ret, const char* name, GLADapiproc proc, int len_args, ...) {
  GLenum err = glad_glGetError();
  if (err == GL_NO_ERROR) return;
  // Straight to stderr: the process is about to abort, whatever the log sinks are.
  std::fprintf(stderr, "penumbra: %s in %s (PENUMBRA_GL_STRICT); call stack:\n", gl_error_name(err), name);
  void* frames[32];
  int n = backtrace(frames, 32);
  backtrace_symbols_fd(frames + 1, n - 1, STDERR_FILENO);
  std::abort();
}
#endif

}  // namespace

const char* gl_error_name(unsigned int e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error";
  }
}

void install_debug_output() {
  if (GLAD_GL_KHR_debug || GLAD_GL_VERSION_4_3) {
    glEnable(GL_DEBUG_OUTPUT);
#ifdef PENUMBRA_GL_STRICT
    // Synchronous messages name the offending call in a debugger, but make drivers serialise
    // their work: strict (dev, asan) builds only.
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
#endif
    glDebugMessageCallback(on_debug_message, nullptr);
  }
#ifdef PENUMBRA_GL_STRICT
  gladSetGLPostCallback(post_call_check);
#endif
}

bool strict_gl_errors() {
#ifdef PENUMBRA_GL_STRICT
  return true;
#else
  return false;
#endif
}

}  // namespace penumbra::gl
