# Every dependency comes from a Debian package (scripts/setup.sh installs them); nothing is downloaded.
find_package(PkgConfig REQUIRED)
find_package(glfw3 CONFIG REQUIRED)
find_package(glm CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)
find_package(spdlog CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(Threads REQUIRED)
find_package(embree 3 CONFIG REQUIRED)
find_package(draco CONFIG REQUIRED)         # glTF KHR_draco_mesh_compression
find_package(meshoptimizer CONFIG REQUIRED)  # glTF EXT_meshopt_compression
find_package(NLopt CONFIG REQUIRED)  # penumbra calibrate: Nelder-Mead
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
# OSMesa and EGL are dlopen'ed at run time; only their headers are needed at build time.
find_path(OSMESA_INCLUDE_DIR GL/osmesa.h REQUIRED)
find_path(EGL_INCLUDE_DIR EGL/egl.h REQUIRED)
find_program(GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT GLAD_EXECUTABLE)
  find_program(GLAD_EXECUTABLE glad REQUIRED)
endif()
if(PENUMBRA_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(PENUMBRA_BUILD_BENCHMARKS)
  find_package(benchmark CONFIG REQUIRED)
endif()
