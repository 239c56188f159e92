#include "exec/gpu_scene.h"

#include <atomic>

#include <glm/gtc/matrix_inverse.hpp>

namespace penumbra::exec {

namespace {
std::uint64_t next_serial() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}
}  // namespace

GpuScene::GpuScene(const scene::Scene& scene) : serial_(next_serial()), scene_(scene) {
  std::vector<scene::Vertex> vertices;
  std::vector<uint32_t> indices;
  for (const scene::Mesh& m : scene_.meshes) {
    ranges_.push_back({static_cast<GLint>(vertices.size()), static_cast<GLsizei>(m.indices.size()),
                       indices.size()});
    vertices.insert(vertices.end(), m.vertices.begin(), m.vertices.end());
    indices.insert(indices.end(), m.indices.begin(), m.indices.end());
  }
  vertices_ = gl::Buffer(vertices.size() * sizeof(scene::Vertex), vertices.data(), false);
  indices_ = gl::Buffer(indices.size() * sizeof(uint32_t), indices.data(), false);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  vao_ = gl::GlHandle<gl::delete_vertex_array>(vao);
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(scene::Vertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  const GLuint offsets[3] = {offsetof(scene::Vertex, position), offsetof(scene::Vertex, normal),
                             offsetof(scene::Vertex, uv)};
  const GLint sizes[3] = {3, 3, 2};
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
    glVertexArrayAttribBinding(vao, a, 0);
  }
  for (const scene::Image& img : scene_.images) {
    int levels = 1;
    for (int s = std::max(img.width, img.height); s > 1; s >>= 1) ++levels;
    gl::Texture t(gl::Format::RGBA8, img.width, img.height, levels);
    // scene::Image rows run top to bottom with glTF's uv (0,0) at the top-left: uploading row 0
    // first puts v = 0 at texture t = 0, so uv need no flip.
    t.upload_bytes(img.pixels.data());
    glGenerateTextureMipmap(t.id());
    t.set_filter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    t.set_wrap(GL_REPEAT);
    textures_.push_back(std::move(t));
  }
}

void GpuScene::draw(const gl::Program& program, GLuint texture_unit, bool alpha_test) const {
  glUseProgram(program.id());
  glBindVertexArray(vao_.id());
  const GLint loc_model = program.uniform_location("u_model");
  const GLint loc_normal = program.uniform_location("u_normal_matrix");
  const GLint loc_color = program.uniform_location("u_base_color");
  const GLint loc_has_tex = program.uniform_location("u_has_texture");
  const GLint loc_tex = program.uniform_location("u_base_texture");
  const GLint loc_cutoff = program.uniform_location("u_alpha_cutoff");
  if (loc_tex >= 0) glProgramUniform1i(program.id(), loc_tex, static_cast<GLint>(texture_unit));
  glDisable(GL_CULL_FACE);  // shadow casters must be closed or double-sided either way
  for (const scene::Instance& inst : scene_.instances) {
    const scene::Mesh& mesh = scene_.meshes[inst.mesh];
    const scene::Material& mat = scene_.materials[mesh.material];
    const MeshRange& r = ranges_[inst.mesh];
    if (loc_model >= 0) glProgramUniformMatrix4fv(program.id(), loc_model, 1, GL_FALSE, &inst.world[0][0]);
    if (loc_normal >= 0) {
      glm::mat3 n = glm::inverseTranspose(glm::mat3(inst.world));
      glProgramUniformMatrix3fv(program.id(), loc_normal, 1, GL_FALSE, &n[0][0]);
    }
    if (loc_color >= 0) glProgramUniform4fv(program.id(), loc_color, 1, &mat.base_color_factor[0]);
    bool textured = mat.base_color_texture >= 0 && mat.base_color_texture < static_cast<int>(textures_.size());
    if (loc_has_tex >= 0) glProgramUniform1i(program.id(), loc_has_tex, textured ? 1 : 0);
    if (textured) glBindTextureUnit(texture_unit, textures_[mat.base_color_texture].id());
    if (loc_cutoff >= 0) {
      float cutoff = alpha_test && mat.alpha_mode == scene::AlphaMode::mask ? mat.alpha_cutoff : -1.0f;
      glProgramUniform1f(program.id(), loc_cutoff, cutoff);
    }
    glDrawElementsBaseVertex(GL_TRIANGLES, r.index_count, GL_UNSIGNED_INT,
                             reinterpret_cast<const void*>(r.first_index * sizeof(uint32_t)), r.base_vertex);
  }
  glBindVertexArray(0);
}

}  // namespace penumbra::exec
