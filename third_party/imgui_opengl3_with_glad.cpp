// The OpenGL3 backend's bundled loader fails under OSMesa; compile the Debian example source
// against glad instead, so the sandbox UI works with every context backend.
#include <glad/gl.h>
#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM
#include "/usr/share/doc/libimgui-dev/examples/backends/imgui_impl_opengl3.cpp"
