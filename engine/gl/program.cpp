#include "gl/program.h"

#include "gl/shader_preprocessor.h"

namespace penumbra::gl {
namespace {

std::string info_log_shader(GLuint s) {
  GLint len = 0;
  glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
  std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
  glGetShaderInfoLog(s, len, nullptr, log.data());
  return log;
}

std::string info_log_program(GLuint p) {
  GLint len = 0;
  glGetProgramiv(p, GL_INFO_LOG_LENGTH, &len);
  std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
  glGetProgramInfoLog(p, len, nullptr, log.data());
  return log;
}

const char* stage_name(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_COMPUTE_SHADER: return "compute";
    default: return "shader";
  }
}

// Compiles one stage; the shader object is returned even on success for attaching.
Result<GLuint> compile_stage(GLenum stage, const std::string& text, const std::vector<std::string>& files) {
  GLuint s = glCreateShader(stage);
  const char* src = text.c_str();
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    Error e = map_compile_log(info_log_shader(s), files, stage_name(stage));
    glDeleteShader(s);
    return e;
  }
  return s;
}

Result<Program> link(const std::vector<GLuint>& shaders, const std::string& what) {
  GLuint p = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(p, s);
  glLinkProgram(p);
  for (GLuint s : shaders) {
    glDetachShader(p, s);
    glDeleteShader(s);
  }
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    Error e = make_error("link failed: " + info_log_program(p));
    e.file = what;
    glDeleteProgram(p);
    return e;
  }
  return Program(p);
}

}  // namespace

glm::ivec3 Program::local_size() const {
  GLint size[3] = {0, 0, 0};
  glGetProgramiv(id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  return {size[0], size[1], size[2]};
}

Result<Program> build_program(const ShaderSources& sources, const ShaderFileSystem& files,
                              std::vector<std::string>* files_used) {
  std::vector<std::pair<GLenum, std::string>> stages;
  if (!sources.compute.empty()) {
    stages.emplace_back(GL_COMPUTE_SHADER, sources.compute);
  } else {
    if (sources.vertex.empty() || sources.fragment.empty())
      return make_error("a graphics program needs a vertex and a fragment shader", ErrorKind::internal);
    stages.emplace_back(GL_VERTEX_SHADER, sources.vertex);
    stages.emplace_back(GL_FRAGMENT_SHADER, sources.fragment);
  }
  std::vector<GLuint> compiled;
  std::vector<ImageDeclaration> images;
  for (const auto& [stage, path] : stages) {
    auto pre = preprocess_shader(path, files, sources.defines);
    if (!pre) {
      for (GLuint s : compiled) glDeleteShader(s);
      return pre.error();
    }
    if (files_used) files_used->insert(files_used->end(), pre->files.begin(), pre->files.end());
    auto s = compile_stage(stage, pre->text, pre->files);
    if (!s) {
      for (GLuint c : compiled) glDeleteShader(c);
      return s.error();
    }
    compiled.push_back(*s);
    if (stage == GL_COMPUTE_SHADER) images = image_declarations(pre->text);
  }
  auto program = link(compiled, stages.front().second);
  if (program) program->set_images(std::move(images));
  return program;
}

Result<Program> build_compute_from_text(const std::string& text) {
  auto s = compile_stage(GL_COMPUTE_SHADER, text, {"<inline>"});
  if (!s) return s.error();
  auto program = link({*s}, "<inline>");
  if (program) program->set_images(image_declarations(text));
  return program;
}

Status ShaderProgram::build() {
  std::vector<std::string> used;
  auto program = build_program(sources_, *files_, &used);
  // Stamps are taken even on failure, so an unchanged broken file is not rebuilt every frame.
  stamps_.clear();
  for (const std::string& f : used)
    if (auto t = files_->modified(f)) stamps_.emplace_back(f, *t);
  if (!program) {
    if (used.empty()) {
      for (const std::string* f : {&sources_.compute, &sources_.vertex, &sources_.fragment})
        if (!f->empty())
          if (auto t = files_->modified(*f)) stamps_.emplace_back(*f, *t);
    }
    last_error_ = program.error();
    return program.error();
  }
  program_ = std::move(*program);
  last_error_.reset();
  return {};
}

bool ShaderProgram::sources_changed() const {
  for (const auto& [path, stamp] : stamps_) {
    auto now = files_->modified(path);
    if (!now || *now != stamp) return true;
  }
  return false;
}

}  // namespace penumbra::gl
