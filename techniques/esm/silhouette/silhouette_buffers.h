#pragma once
// The silhouette quads of a scene in static GPU buffers: one vertex buffer, one index buffer and
// one vertex array per mesh (object space), built once from the CPU builder and drawn for every
// instance of the mesh with its world matrix. Shared by every pass that draws quads: a pass
// holds the shared_ptr; the cache only remembers it (weak_ptr), so the GL objects die with the
// last pass that uses them, while a GL context is current.
//
// Vertex attributes (silhouette_quad.vert.glsl): 0 position, 1 other_end, 2 plane,
// 3 other_plane, 4 extrusion (QuadVertex).
//
//   Result<std::shared_ptr<SilhouetteBuffers>> b = SilhouetteBuffers::for_scene(*frame.scene);
//   (*b)->draw(program);  // sets u_model and u_plane_matrix per instance
#include <memory>
#include <vector>

#include "exec/gpu_scene.h"
#include "gl/buffer.h"
#include "gl/gl_handle.h"
#include "gl/program.h"
#include "techniques/esm/silhouette/silhouette_quads.h"
#include "util/error.h"

namespace penumbra::esm {

class SilhouetteBuffers {
 public:
  // The buffers of `scene`, built on first use (and again when a different scene is set).
  // Errors: a mesh with more quads than the buffers hold (the Error names it).
  static Result<std::shared_ptr<SilhouetteBuffers>> for_scene(const exec::GpuScene& scene);

  // Draws the quads of every instance (meshes without quads are skipped): sets u_model (object
  // -> world) and u_plane_matrix (its inverse transpose: object planes -> world planes).
  void draw(const gl::Program& program) const;

  const SilhouetteStats& totals() const { return totals_; }
  size_t quads() const { return totals_.quads; }

 private:
  struct MeshBuffers {
    gl::Buffer vertices, indices;
    gl::GlHandle<gl::delete_vertex_array> vao;
    GLsizei index_count = 0;
  };
  explicit SilhouetteBuffers(std::vector<scene::Instance> instances) : instances_(std::move(instances)) {}
  std::vector<scene::Instance> instances_;  // a copy: the buffers may outlive the GpuScene
  std::vector<MeshBuffers> meshes_;
  SilhouetteStats totals_;
};

}  // namespace penumbra::esm
