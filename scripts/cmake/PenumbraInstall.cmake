# `cmake --install`: the executables, libpenumbra, the public headers, the shared passes' and the
# engine's shaders, and a versioned CMake package, so a plugin or a test is built against an
# installed Penumbra with
#
#   find_package(Penumbra 0.1 CONFIG REQUIRED)
#   penumbra_add_plugin(NAME vsm SOURCES ... FILES ...)            # links Penumbra::passes
#   target_link_libraries(my_tests PRIVATE Penumbra::test_support)  # docs/testing.md
#
# Layout under the prefix:
#   bin/penumbra, bin/penumbra-sandbox        run against lib/ ($ORIGIN/../lib)
#   lib/libpenumbra.so.0                      Penumbra::engine (and Penumbra::passes)
#   lib/libpenumbra_techniques.a              Penumbra::techniques (the built-ins, for plugins' tests)
#   lib/libpenumbra_reference_rt.a            Penumbra::reference (the ray-traced reference; Embree)
#   lib/libpenumbra_test_support.a            Penumbra::test_support
#   include/penumbra/{gl,graph,exec,technique,plugin,scene,metrics,util}/  engine headers
#   include/penumbra/{passes,techniques,test_support}/  pass, built-in technique and test
#                                             support headers
#   include/penumbra/{glad,KHR}/              the GL loader this libpenumbra was built with
#   share/penumbra/shaders/                   passes/**.glsl and engine/gl/shaders (also
#                                             embedded in libpenumbra; installed to read)
#   lib/cmake/Penumbra/                       PenumbraConfig[Version].cmake, targets,
#                                             PenumbraPlugin.cmake (penumbra_add_plugin)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PENUMBRA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Penumbra)
set(PENUMBRA_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/penumbra)

set(install_targets penumbra_engine penumbra_passes penumbra_techniques penumbra_reference_rt)
set(PENUMBRA_INSTALL_TEST_SUPPORT OFF)
if(TARGET penumbra_test_support)
  list(APPEND install_targets penumbra_test_support)
  set(PENUMBRA_INSTALL_TEST_SUPPORT ON)
endif()
if(PENUMBRA_SANITIZE)
  # An instrumented install (the asan preset): whoever links its libraries needs the sanitizer
  # runtimes, which the build tree gets from add_link_options().
  foreach(target ${install_targets})
    target_link_options(${target} INTERFACE $<INSTALL_INTERFACE:-fsanitize=address,undefined>)
  endforeach()
endif()
install(TARGETS ${install_targets} EXPORT PenumbraTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

set(executables penumbra)
if(TARGET penumbra-sandbox)
  list(APPEND executables penumbra-sandbox)
endif()
set_target_properties(${executables} PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
install(TARGETS ${executables} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Headers keep their include paths: "technique/technique.h", "passes/common/shadow_uniforms.h".
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/ DESTINATION ${PENUMBRA_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/passes DESTINATION ${PENUMBRA_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/techniques DESTINATION ${PENUMBRA_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h" PATTERN "_template" EXCLUDE)
if(TARGET penumbra_test_support)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/test_support DESTINATION ${PENUMBRA_INSTALL_INCLUDEDIR}
    FILES_MATCHING PATTERN "*.h")
endif()
install(DIRECTORY ${PENUMBRA_GLAD_INCLUDE_DIR}/ DESTINATION ${PENUMBRA_INSTALL_INCLUDEDIR})

install(DIRECTORY ${PROJECT_SOURCE_DIR}/passes DESTINATION ${CMAKE_INSTALL_DATADIR}/penumbra/shaders
  FILES_MATCHING PATTERN "*.glsl")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/gl/shaders
  DESTINATION ${CMAKE_INSTALL_DATADIR}/penumbra/shaders/engine/gl)

install(EXPORT PenumbraTargets NAMESPACE Penumbra:: DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/scripts/cmake/PenumbraConfig.cmake.in
  ${PROJECT_BINARY_DIR}/PenumbraConfig.cmake INSTALL_DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR}
  PATH_VARS PENUMBRA_INSTALL_INCLUDEDIR CMAKE_INSTALL_BINDIR CMAKE_INSTALL_DATADIR)
# 0.x: a minor version may break the plugin ABI, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/PenumbraConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/PenumbraConfig.cmake ${PROJECT_BINARY_DIR}/PenumbraConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/scripts/cmake/PenumbraPlugin.cmake
  DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})
