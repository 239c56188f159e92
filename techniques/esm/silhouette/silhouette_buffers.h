#pragma once
// The silhouette quads of a scene on the GPU, built once from the CPU builder, and the two steps
// that turn them into this frame's silhouettes without a read-back:
//  - find(): a compute pass tests every quad of every instance against the light (the light in
//    front of exactly one of its planes: is_silhouette) and appends the silhouettes to a list,
//    counting them into an indirect draw command;
//  - draw_found(): draws the listed quads, indirectly, four vertices each through a fixed index
//    buffer; the vertex shader builds the quad's corners from its record.
//  - or, instead of drawing them, compute writes their texels (shaders/silhouette_write.comp.glsl:
//    one work group a listed quad, dispatched indirectly from the count find() wrote, then one
//    per chunk of four columns of the long quads, which the first pass lists).
// Or, the paper's way, draw_all(): every quad of every instance, and the vertex shader collapses
// those that are no silhouette (Figure 4). On small scenes and maps that is cheaper than the
// dispatches and barriers (kComputeAboveQuads). Raster work grows with the silhouettes, not with the mesh.
// One storage buffer holds every mesh's quads (SilhouetteQuad records, 68 bytes each), one the
// instances (world matrix, plane matrix, where the mesh's quads start). Shared by every pass
// that draws quads: a pass holds the shared_ptr; the cache only remembers it (weak_ptr), so the
// GL objects die with the last pass that uses them, while a GL context is current.
//
//   Result<std::shared_ptr<SilhouetteBuffers>> b = SilhouetteBuffers::for_scene(*frame.scene);
//   (*b)->find(find_program, light);          // shaders/silhouette_find.comp.glsl
//   (*b)->draw_found(quad_program);           // shaders/silhouette_quad.vert.glsl, per face
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "exec/gpu_scene.h"
#include "gl/buffer.h"
#include "gl/gl_handle.h"
#include "gl/program.h"
#include "techniques/esm/silhouette/silhouette_quads.h"
#include "util/error.h"

namespace penumbra::esm {

// The storage-buffer bindings of shaders/silhouette_records.glsl. The shaders get them as
// defines (silhouette_shader_defines), so these numbers are the only place they are written.
struct SilhouetteBindings {
  static constexpr unsigned quads = 0, instances = 1, list = 2, command = 3, chunks = 4;
};
std::vector<std::pair<std::string, std::string>> silhouette_shader_defines();

// Work-group size of the finding pass (its local_size_x, passed as a define as well).
inline constexpr unsigned kFindGroupSize = 256;

// What silhouette_finding=auto picks: the compute writer above this many quads over all
// instances, or on maps this many texels wide and wider; below both, every quad drawn. Measured
// on an H200 (1080p; docs/results/esm.md), silhouette pass in ms, drawing every quad / compute:
// at 512^2 CesiumMilkTruck (2,209 quads) 0.030 / 0.035, colonnade (2,652) 0.035 / 0.035,
// showcase (5,589) 0.043 / 0.035, FlightHelmet (87,257) 0.293 / 0.050; at 2048^2 ball (2,264)
// 0.029 / 0.033, colonnade 0.083 / 0.040, FlightHelmet 0.328 / 0.063. The compute writer costs
// three dispatches and two barriers whatever the scene (about 0.03 ms); the raster grows with
// the quads and their texels. Finding first and drawing the found (gpu) was never the fastest.
inline constexpr size_t kComputeAboveQuads = 4096;
inline constexpr int kComputeFromMapSize = 2048;

class SilhouetteBuffers {
 public:
  // The buffers of `scene` with `options`, built on first use (and again when a different scene
  // or other options are set). Errors: a mesh with more edges than the builder takes (the Error names it); a scene whose
  // quads or silhouette list exceed the GL's largest storage buffer; a GL whose vertex shaders
  // cannot read three storage buffers.
  static Result<std::shared_ptr<SilhouetteBuffers>> for_scene(const exec::GpuScene& scene,
                                                               const SilhouetteOptions& options = {});

  // This frame's silhouettes from `light` (homogeneous: (position, 1), or (-direction, 0)) into
  // the list and the draw command. Ends with the barriers the indirect draw needs.
  void find(const gl::Program& find_program, const glm::vec4& light) const;
  // Draws the quads the last find() listed with `program` (indirect, indexed).
  void draw_found(const gl::Program& program) const;
  // Binds the records, the last find()'s list and the chunk list for the compute writer
  // (shaders/silhouette_write.comp.glsl): its first pass runs one work group per listed quad,
  // glDispatchComputeIndirect of command() at kWriteCommandOffset; its second one per chunk the
  // first listed, of chunks() at kChunkDispatchOffset. reset_chunks() empties the chunk list
  // before each first pass.
  void bind_found() const;
  void reset_chunks() const;
  const gl::Buffer& command() const { return command_; }
  const gl::Buffer& chunks() const { return chunks_; }
  static constexpr GLintptr kWriteCommandOffset = 5 * sizeof(std::uint32_t);  // after the draw command
  static constexpr GLintptr kChunkDispatchOffset = 2 * sizeof(std::uint32_t);  // after count, groups done
  // Whether one work group per quad fits in a dispatch on this GL, whatever find() lists
  // (GL_MAX_COMPUTE_WORK_GROUP_COUNT: 65,535 is all a GL must allow).
  bool can_write_found() const { return instance_quads_ <= max_write_groups_; }
  // Draws every quad with `program`; those that are no silhouette collapse in the vertex shader.
  void draw_all(const gl::Program& program) const;
  // How many quads the last find() listed (a read-back: for tests and statistics only).
  size_t found() const;
  // The compute writer's dispatch the last find() counted (a read-back, for tests).
  std::array<std::uint32_t, 3> write_groups() const;

  const SilhouetteStats& totals() const { return totals_; }
  size_t quads() const { return totals_.quads; }
  // Quads over all instances: the finding pass's threads, and the list's capacity.
  size_t instance_quads() const { return instance_quads_; }

 private:
  SilhouetteBuffers() = default;
  void bind_records(const gl::Buffer& list) const;
  void draw(const gl::Program& program, const gl::Buffer& list, const gl::Buffer& command) const;
  gl::Buffer quads_, instances_, list_, command_, indices_, chunks_;
  gl::Buffer all_list_, all_command_;  // every (instance, quad), and the command that draws them
  gl::GlHandle<gl::delete_vertex_array> vao_;  // empty: the vertex shader reads the buffers
  SilhouetteStats totals_;
  size_t instance_count_ = 0, instance_quads_ = 0, max_write_groups_ = 0, chunk_capacity_ = 0;
};

}  // namespace penumbra::esm
