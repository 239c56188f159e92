#pragma once
// KHR_debug messages go to spdlog. In strict builds (PENUMBRA_GL_STRICT, the dev and asan
// presets) any GL error aborts at once, naming the GL function and the call stack that led to
// it, so a bug is caught where it happens rather than frames later.
namespace penumbra::gl {

void install_debug_output();

// "GL_INVALID_OPERATION" etc. for a glGetError code.
const char* gl_error_name(unsigned int error);

// Strict builds only: true while the post-call hook is armed.
bool strict_gl_errors();

}  // namespace penumbra::gl
