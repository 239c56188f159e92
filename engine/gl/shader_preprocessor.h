#pragma once
// Resolves #include "file" in GLSL and keeps line numbers right across files.
//
// Each file gets a source-string number k; the output carries `#line k*kLinesPerShaderFile+N k`
// after every include boundary, so the driver's "0:12(3): error" (Mesa) or "3(12) : error"
// (NVIDIA) can be mapped back to "passes/blur/blur.comp.glsl:12" from the line alone where the
// driver reports the wrong source string. Includes resolve relative to the including
// file first, then through the file system's include directories (shader_files.h); a name with
// `..` or an absolute one is an error, as it never needs to climb. A file included twice is
// pasted once (include guards are implicit). #version stays the first line; defines follow it.
#include <string>
#include <utility>
#include <vector>

#include "gl/shader_files.h"
#include "util/error.h"

namespace penumbra::gl {

// Lines of one file the mapping can tell apart (no shader comes near).
inline constexpr int kLinesPerShaderFile = 100000;

struct PreprocessedShader {
  std::string text;                // what is handed to glShaderSource
  std::vector<std::string> files;  // source-string number -> path (0 is the top file)
};

Result<PreprocessedShader> preprocess_shader(
    const std::string& path, const ShaderFileSystem& files,
    const std::vector<std::pair<std::string, std::string>>& defines = {});

// Rewrites a driver's info log so every "N:line" or "N(line)" names the file, and fills an
// Error with the first error's file and line.
Error map_compile_log(const std::string& log, const std::vector<std::string>& files,
                      const std::string& stage);

}  // namespace penumbra::gl
