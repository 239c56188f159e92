# Embeds every .glsl file (and the techniques' graph .json files) of the source tree into a generated C++ source, so installed or
# bundled binaries carry their shaders. Development builds still read the files from the tree
# first (hot reload); see engine/gl/shader_files.h.
set(PENUMBRA_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_shaders.cmake)

function(penumbra_embed_shaders target)
  file(GLOB_RECURSE shader_files CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}
       ${PROJECT_SOURCE_DIR}/engine/*.glsl ${PROJECT_SOURCE_DIR}/passes/*.glsl
       ${PROJECT_SOURCE_DIR}/techniques/*.glsl ${PROJECT_SOURCE_DIR}/sandbox/*.glsl
       ${PROJECT_SOURCE_DIR}/tests/*.glsl
       ${PROJECT_SOURCE_DIR}/techniques/*.json ${PROJECT_SOURCE_DIR}/passes/*.json)
  set(out ${CMAKE_BINARY_DIR}/generated/embedded_shaders.cpp)
  set(abs_files "")
  foreach(f ${shader_files})
    list(APPEND abs_files ${PROJECT_SOURCE_DIR}/${f})
  endforeach()
  string(REPLACE ";" "|" files_arg "${shader_files}")  # keep the list one shell word
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR} "-DFILES=${files_arg}" -DOUT=${out}
            -P ${PENUMBRA_EMBED_SCRIPT}
    DEPENDS ${abs_files} ${PENUMBRA_EMBED_SCRIPT}
    COMMENT "Embedding shader files"
    VERBATIM)
  target_sources(${target} PRIVATE ${out})
endfunction()
