#pragma once
// A scene::Scene on the GPU: one vertex and one index buffer for all meshes, one texture per
// image (mipmapped), and a draw call per instance. Raster passes (G-buffer, shadow maps,
// reference accumulation) draw through it with their own program, which declares
//   layout(location = 0) in vec3 a_position;  layout(location = 1) in vec3 a_normal;
//   layout(location = 2) in vec2 a_uv;
//   uniform mat4 u_model; uniform mat3 u_normal_matrix;
//   uniform vec4 u_base_color; uniform int u_has_texture; uniform sampler2D u_base_texture;
//   uniform float u_alpha_cutoff;   // < 0: opaque, no alpha test
// (any of them may be left out; unused uniforms are skipped).
#include <cstdint>
#include <memory>
#include <vector>

#include "gl/buffer.h"
#include "gl/gl_handle.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "scene/scene.h"

namespace penumbra::exec {

class GpuScene {
 public:
  explicit GpuScene(const scene::Scene& scene);
  const scene::Scene& cpu() const { return scene_; }
  // Binds the vertex array and draws every instance. `texture_unit` receives base colour
  // textures. With alpha_test=false, masked materials draw as opaque (u_alpha_cutoff = -1).
  void draw(const gl::Program& program, GLuint texture_unit = 0, bool alpha_test = true) const;
  size_t triangle_count() const { return scene_.triangle_count(); }
  // Different for every GpuScene the process makes, never reused (an address is, by the next
  // scene allocated there): what a cache of something built from the scene is keyed by. A
  // GpuScene does not change after construction, so equal serials mean equal scenes.
  std::uint64_t serial() const { return serial_; }

 private:
  struct MeshRange {
    GLint base_vertex;
    GLsizei index_count;
    size_t first_index;
  };
  std::uint64_t serial_;
  scene::Scene scene_;  // kept for the CPU reference, metrics and bounds
  gl::Buffer vertices_, indices_;
  gl::GlHandle<gl::delete_vertex_array> vao_;
  std::vector<MeshRange> ranges_;
  std::vector<gl::Texture> textures_;
};

}  // namespace penumbra::exec
