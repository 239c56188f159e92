#pragma once
// A linked GL program (graphics or compute) built from preprocessed GLSL files, and
// ShaderProgram, which rebuilds it from disk on request and keeps the last good program when a
// new source fails to compile.
//
//   gl::ShaderProgram blur({.compute = "passes/blur/blur.comp.glsl"});
//   if (Status s = blur.build(); !s) log(s.error().to_string());   // "passes/blur/...:12: ..."
//   glUseProgram(blur.id());
//   ...
//   if (blur.sources_changed()) blur.reload();  // on failure the old program stays in use
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl_handle.h"
#include "gl/image_declarations.h"
#include "gl/shader_files.h"
#include "util/error.h"

namespace penumbra::gl {

// The name of element `index` of a uniform array: "u_faces[3]". (Appended piece by piece: GCC 12
// warns falsely (-Wrestrict) on `name + "[" + std::to_string(index)`.)
inline std::string uniform_element(const char* array, int index) {
  std::string name(array);
  name.append("[").append(std::to_string(index)).append("]");
  return name;
}

class Program {
 public:
  Program() = default;
  explicit Program(GLuint id) : handle_(id) {}
  GLuint id() const { return handle_.id(); }
  explicit operator bool() const { return static_cast<bool>(handle_); }

  GLint uniform_location(const char* name) const { return glGetUniformLocation(id(), name); }
  // Setters ignore uniforms the compiler optimised away (location -1), as GL does.
  void set(const char* name, int v) const { glProgramUniform1i(id(), uniform_location(name), v); }
  void set(const char* name, float v) const { glProgramUniform1f(id(), uniform_location(name), v); }
  void set(const char* name, glm::vec2 v) const { glProgramUniform2f(id(), uniform_location(name), v.x, v.y); }
  void set(const char* name, glm::vec3 v) const { glProgramUniform3f(id(), uniform_location(name), v.x, v.y, v.z); }
  void set(const char* name, glm::vec4 v) const { glProgramUniform4f(id(), uniform_location(name), v.x, v.y, v.z, v.w); }
  void set(const char* name, glm::ivec2 v) const { glProgramUniform2i(id(), uniform_location(name), v.x, v.y); }
  void set(const char* name, const glm::mat4& m) const {
    glProgramUniformMatrix4fv(id(), uniform_location(name), 1, GL_FALSE, &m[0][0]);
  }
  // Work-group size declared by a compute shader's layout(local_size_*).
  glm::ivec3 local_size() const;
  // The compute shader's image uniforms with a binding and format (gl/image_declarations.h).
  const std::vector<ImageDeclaration>& images() const { return images_; }
  void set_images(std::vector<ImageDeclaration> images) { images_ = std::move(images); }

 private:
  GlHandle<delete_program> handle_;
  std::vector<ImageDeclaration> images_;
};

struct ShaderSources {
  std::string vertex, fragment, compute;  // repository-relative paths; compute XOR vertex+fragment
  std::vector<std::pair<std::string, std::string>> defines;
};

// Compiles and links once. Errors name the file and line of the first error; details hold the
// whole mapped log.
Result<Program> build_program(const ShaderSources& sources, const ShaderFileSystem& files,
                              std::vector<std::string>* files_used = nullptr);
// For tests and small tools: compiles GLSL text given inline (no includes).
Result<Program> build_compute_from_text(const std::string& text);

class ShaderProgram {
 public:
  explicit ShaderProgram(ShaderSources sources,
                         const ShaderFileSystem& files = ShaderFileSystem::default_instance())
      : sources_(std::move(sources)), files_(&files) {}

  // Builds from the current sources; on failure keeps the previous program (if any) and
  // records the error.
  Status build();
  Status reload() { return build(); }
  // True when any file the last build read has a newer modification time on disk.
  bool sources_changed() const;

  GLuint id() const { return program_.id(); }
  const Program& program() const { return program_; }
  bool valid() const { return static_cast<bool>(program_); }
  const std::optional<Error>& last_error() const { return last_error_; }
  void set_defines(std::vector<std::pair<std::string, std::string>> d) { sources_.defines = std::move(d); }

 private:
  ShaderSources sources_;
  const ShaderFileSystem* files_;
  Program program_;
  std::optional<Error> last_error_;
  std::vector<std::pair<std::string, std::filesystem::file_time_type>> stamps_;
};

}  // namespace penumbra::gl
