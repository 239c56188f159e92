#include "techniques/esm/silhouette/silhouette_buffers.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <mutex>

#include <glm/gtc/matrix_inverse.hpp>
#include <spdlog/spdlog.h>

namespace penumbra::esm {
namespace {

// One remembered scene, by GpuScene::serial() (an address is reused by the next scene made
// there), like the Embree cache.
struct Cache {
  std::mutex mutex;
  std::uint64_t scene = 0;
  std::weak_ptr<SilhouetteBuffers> buffers;
};

Cache& cache() {
  static Cache c;
  return c;
}

void add(SilhouetteStats& total, const SilhouetteStats& s) {
  total.welded_vertices += s.welded_vertices;
  total.facets += s.facets;
  total.degenerate_triangles += s.degenerate_triangles;
  total.edges += s.edges;
  total.coplanar += s.coplanar;
  total.concave += s.concave;
  total.convex += s.convex;
  total.beveled += s.beveled;
  total.open += s.open;
  total.non_manifold += s.non_manifold;
  total.inconsistent += s.inconsistent;
  total.quads += s.quads;
}

}  // namespace

Result<std::shared_ptr<SilhouetteBuffers>> SilhouetteBuffers::for_scene(const exec::GpuScene& gpu) {
  Cache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  const scene::Scene& s = gpu.cpu();
  if (auto alive = c.buffers.lock(); alive && c.scene == gpu.serial()) return alive;
  const auto t0 = std::chrono::steady_clock::now();
  Result<std::vector<SilhouetteGeometry>> geometry = build_scene_silhouettes(s);
  if (!geometry) return geometry.error();
  std::shared_ptr<SilhouetteBuffers> out(new SilhouetteBuffers(s.instances));
  for (const SilhouetteGeometry& g : *geometry) {
    add(out->totals_, g.stats);
    MeshBuffers m;
    m.index_count = static_cast<GLsizei>(g.indices.size());
    if (m.index_count > 0) {
      m.vertices = gl::Buffer(g.vertices.size() * sizeof(QuadVertex), g.vertices.data(), false);
      m.indices = gl::Buffer(g.indices.size() * sizeof(uint32_t), g.indices.data(), false);
      GLuint vao = 0;
      glCreateVertexArrays(1, &vao);
      m.vao = gl::GlHandle<gl::delete_vertex_array>(vao);
      glVertexArrayVertexBuffer(vao, 0, m.vertices.id(), 0, sizeof(QuadVertex));
      glVertexArrayElementBuffer(vao, m.indices.id());
      const GLuint offsets[5] = {offsetof(QuadVertex, position), offsetof(QuadVertex, other_end),
                                 offsetof(QuadVertex, plane), offsetof(QuadVertex, other_plane),
                                 offsetof(QuadVertex, extrusion)};
      const GLint sizes[5] = {3, 3, 4, 4, 3};
      for (GLuint a = 0; a < 5; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao, a, 0);
      }
    }
    out->meshes_.push_back(std::move(m));
  }
  const SilhouetteStats& t = out->totals_;
  spdlog::info("esm: {} silhouette quads for {} edges of {} triangles ({} open, {} non-manifold, {} bevelled, "
               "{} degenerate triangles skipped) built in {:.0f} ms",
               t.quads, t.edges, t.facets, t.open, t.non_manifold, t.beveled, t.degenerate_triangles,
               std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  c.scene = gpu.serial();
  c.buffers = out;
  return out;
}

void SilhouetteBuffers::draw(const gl::Program& program) const {
  glUseProgram(program.id());
  const GLint loc_model = program.uniform_location("u_model");
  const GLint loc_planes = program.uniform_location("u_plane_matrix");
  for (const scene::Instance& inst : instances_) {
    if (inst.mesh >= meshes_.size() || meshes_[inst.mesh].index_count == 0) continue;
    const MeshBuffers& m = meshes_[inst.mesh];
    // Planes are covectors: a world plane is transpose(inverse(M)) times the object plane.
    const glm::mat4 planes = glm::inverseTranspose(inst.world);
    glProgramUniformMatrix4fv(program.id(), loc_model, 1, GL_FALSE, &inst.world[0][0]);
    glProgramUniformMatrix4fv(program.id(), loc_planes, 1, GL_FALSE, &planes[0][0]);
    glBindVertexArray(m.vao.id());
    glDrawElements(GL_TRIANGLES, m.index_count, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
}

}  // namespace penumbra::esm
