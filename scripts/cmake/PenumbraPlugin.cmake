# penumbra_add_plugin(): a technique plugin as a complete plugin directory. Shipped with the
# package (find_package(Penumbra) includes it) and used in the tree for the tests' plugins.
#
#   penumbra_add_plugin(NAME vsm
#     SOURCES vsm_technique.cpp vsm_passes.cpp
#     FILES vsm/vsm.json vsm/vsm_moments.frag.glsl)
#
# builds NAME.so (a MODULE, no "lib" prefix) linking Penumbra::passes, i.e. libpenumbra, the one
# engine the host uses too, into OUTPUT_DIRECTORY (default ${CMAKE_CURRENT_BINARY_DIR}/plugins),
# and copies FILES (the graph JSON and GLSL the plugin reads; paths relative to FILES_BASE,
# default the calling CMakeLists.txt's folder) there, keeping those relative paths. A plugin's graph_file and
# shader paths are those relative paths: the host reads them from beside the .so. Pass the
# directory to `--plugin-dir`. With INSTALL_DESTINATION, `cmake --install` puts the .so and
# the files under it the same way.
#
# Options: NAME, SOURCES, FILES, FILES_BASE, OUTPUT_DIRECTORY, OUTPUT_NAME (default NAME),
# INSTALL_DESTINATION.
function(penumbra_add_plugin)
  cmake_parse_arguments(P "" "NAME;FILES_BASE;OUTPUT_DIRECTORY;OUTPUT_NAME;INSTALL_DESTINATION" "SOURCES;FILES" ${ARGN})
  if(NOT P_NAME OR NOT P_SOURCES)
    message(FATAL_ERROR "penumbra_add_plugin: NAME and SOURCES are required")
  endif()
  if(NOT P_FILES_BASE)
    set(P_FILES_BASE ${CMAKE_CURRENT_SOURCE_DIR})
  endif()
  if(NOT P_OUTPUT_DIRECTORY)
    set(P_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/plugins)
  endif()
  if(NOT P_OUTPUT_NAME)
    set(P_OUTPUT_NAME ${P_NAME})
  endif()

  add_library(${P_NAME} MODULE ${P_SOURCES})
  target_link_libraries(${P_NAME} PRIVATE Penumbra::passes)
  set_target_properties(${P_NAME} PROPERTIES PREFIX "" OUTPUT_NAME ${P_OUTPUT_NAME}
                        LIBRARY_OUTPUT_DIRECTORY ${P_OUTPUT_DIRECTORY})

  # Each file is copied when it changes; listing the copies as sources makes the build do it.
  set(copies "")
  foreach(f ${P_FILES})
    get_filename_component(abs ${f} ABSOLUTE BASE_DIR ${P_FILES_BASE})
    file(RELATIVE_PATH rel ${P_FILES_BASE} ${abs})
    set(copy ${P_OUTPUT_DIRECTORY}/${rel})
    add_custom_command(OUTPUT ${copy}
      COMMAND ${CMAKE_COMMAND} -E copy_if_different ${abs} ${copy}
      DEPENDS ${abs} VERBATIM)
    list(APPEND copies ${copy})
    if(P_INSTALL_DESTINATION)
      get_filename_component(rel_dir ${rel} DIRECTORY)
      install(FILES ${abs} DESTINATION ${P_INSTALL_DESTINATION}/${rel_dir})
    endif()
  endforeach()
  target_sources(${P_NAME} PRIVATE ${copies})
  if(P_INSTALL_DESTINATION)
    install(TARGETS ${P_NAME} LIBRARY DESTINATION ${P_INSTALL_DESTINATION})
  endif()
endfunction()
