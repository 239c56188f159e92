#include "techniques/esm/silhouette/silhouette_buffers.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <mutex>

#include <glm/gtc/matrix_inverse.hpp>
#include <spdlog/spdlog.h>

namespace penumbra::esm {
namespace {

// One instance as shaders/silhouette_records.glsl reads it (std430: 144 bytes).
struct InstanceRecord {
  glm::mat4 model{1.0f};   // object -> world
  glm::mat4 planes{1.0f};  // inverse transpose of model: planes are covectors
  std::uint32_t first_quad = 0, quad_count = 0;
  std::uint32_t first_slot = 0;  // this instance's first thread of the finding pass
  std::uint32_t unused = 0;
};
static_assert(sizeof(InstanceRecord) == 144);

// glDrawElementsIndirect's command; find() counts six indices per silhouette into `count`.
struct DrawCommand {
  std::uint32_t count = 0, instance_count = 1, first_index = 0, base_vertex = 0, base_instance = 0;
};

// What find() writes (shaders/silhouette_find.comp.glsl's SilhouetteCommand): the draw command,
// then glDispatchComputeIndirect's for the compute writer, one work group per silhouette.
struct FindCommand {
  DrawCommand draw;
  std::uint32_t write_groups = 0, write_groups_y = 1, write_groups_z = 1;
};
static_assert(offsetof(FindCommand, write_groups) == SilhouetteBuffers::kWriteCommandOffset);

// The chunk list's header (shaders/silhouette_write.comp.glsl's SilhouetteChunks), before its
// (list entry, first column) pairs.
struct ChunkHeader {
  std::uint32_t count = 0, groups_done = 0;
  std::uint32_t groups = 0, groups_y = 1, groups_z = 1;  // the second pass's dispatch
  std::uint32_t capacity = 0, unused0 = 0, unused1 = 0;
};
static_assert(offsetof(ChunkHeader, groups) == SilhouetteBuffers::kChunkDispatchOffset);
static_assert(sizeof(ChunkHeader) == 32);

// Chunks the list holds per instance quad (and at least kMinChunks): a chunk is four columns of
// a quad, and only quads longer than two chunks are listed (longer ones are written in place
// once it is full). FlightHelmet at 2048^2 lists about 0.4 a quad.
constexpr size_t kChunksPerQuad = 4, kMinChunks = 65536;

// One remembered scene, by GpuScene::serial() (an address is reused by the next scene made
// there), like the Embree cache.
struct Cache {
  std::mutex mutex;
  std::uint64_t scene = 0;
  bool alpha_contours = true;
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
  total.alpha_contours += s.alpha_contours;
  total.alpha_skipped += s.alpha_skipped;
}

GLint gl_limit(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

std::string mib(size_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

}  // namespace

std::vector<std::pair<std::string, std::string>> silhouette_shader_defines() {
  return {{"SILHOUETTE_QUADS_BINDING", std::to_string(SilhouetteBindings::quads)},
          {"SILHOUETTE_INSTANCES_BINDING", std::to_string(SilhouetteBindings::instances)},
          {"SILHOUETTE_LIST_BINDING", std::to_string(SilhouetteBindings::list)},
          {"SILHOUETTE_COMMAND_BINDING", std::to_string(SilhouetteBindings::command)},
          {"SILHOUETTE_CHUNKS_BINDING", std::to_string(SilhouetteBindings::chunks)},
          {"SILHOUETTE_FIND_GROUP", std::to_string(kFindGroupSize)}};
}

Result<std::shared_ptr<SilhouetteBuffers>> SilhouetteBuffers::for_scene(const exec::GpuScene& gpu,
                                                                         const SilhouetteOptions& options) {
  Cache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  const scene::Scene& s = gpu.cpu();
  if (auto alive = c.buffers.lock(); alive && c.scene == gpu.serial() && c.alpha_contours == options.alpha_contours)
    return alive;
  if (const GLint blocks = gl_limit(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS); blocks < 3)
    return make_error("esm: this OpenGL lets a vertex shader read " + std::to_string(blocks) +
                      " storage buffers; the silhouette quads need 3 (GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS)");
  const auto t0 = std::chrono::steady_clock::now();
  Result<std::vector<SilhouetteGeometry>> geometry = build_scene_silhouettes(s, options);
  if (!geometry) return geometry.error();
  std::shared_ptr<SilhouetteBuffers> out(new SilhouetteBuffers());
  std::vector<SilhouetteQuad> quads;
  std::vector<size_t> first_quad(geometry->size(), 0);
  for (size_t m = 0; m < geometry->size(); ++m) {
    const SilhouetteGeometry& g = (*geometry)[m];
    add(out->totals_, g.stats);
    first_quad[m] = quads.size();
    quads.insert(quads.end(), g.quads.begin(), g.quads.end());
  }
  std::vector<InstanceRecord> instances;
  std::vector<std::uint32_t> all;  // (instance, quad) pairs, in slot order
  size_t slots = 0;
  for (const scene::Instance& inst : s.instances) {
    if (inst.mesh >= geometry->size() || (*geometry)[inst.mesh].quads.empty()) continue;
    InstanceRecord r;
    r.model = inst.world;
    r.planes = glm::inverseTranspose(inst.world);
    r.first_quad = static_cast<std::uint32_t>(first_quad[inst.mesh]);
    r.quad_count = static_cast<std::uint32_t>((*geometry)[inst.mesh].quads.size());
    r.first_slot = static_cast<std::uint32_t>(slots);
    slots += r.quad_count;
    for (std::uint32_t q = 0; q < r.quad_count; ++q)
      all.insert(all.end(), {static_cast<std::uint32_t>(instances.size()), r.first_quad + q});
    instances.push_back(r);
  }
  // Every buffer is one storage block: each must fit the largest one the GL allows; the finding
  // pass counts six indices per instance quad in 32 bits.
  const size_t largest = static_cast<size_t>(std::max<GLint>(gl_limit(GL_MAX_SHADER_STORAGE_BLOCK_SIZE), 0));
  const size_t quad_bytes = quads.size() * sizeof(SilhouetteQuad), list_bytes = slots * 2 * sizeof(std::uint32_t);
  if (std::max(quad_bytes, list_bytes) > largest || slots > UINT32_MAX / 6)
    return make_error("esm: the scene has " + std::to_string(quads.size()) + " silhouette quads (" +
                      std::to_string(slots) + " over its instances), which need storage buffers of " +
                      mib(quad_bytes) + " and " + mib(list_bytes) + "; this OpenGL's largest is " + mib(largest) +
                      " (GL_MAX_SHADER_STORAGE_BLOCK_SIZE): use fewer or simpler meshes, or another technique");
  out->instance_count_ = instances.size();
  out->instance_quads_ = slots;
  if (slots > 0) {
    out->quads_ = gl::Buffer::from<SilhouetteQuad>(quads);
    out->instances_ = gl::Buffer::from<InstanceRecord>(instances);
    out->list_ = gl::Buffer(list_bytes, nullptr, false);
    const FindCommand empty;
    out->command_ = gl::Buffer(sizeof empty, &empty, true);
    GLint max_groups = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &max_groups);
    out->max_write_groups_ = static_cast<size_t>(std::max(max_groups, 0));
    out->chunk_capacity_ = std::min({std::max(kChunksPerQuad * slots, kMinChunks), out->max_write_groups_,
                                     (largest - sizeof(ChunkHeader)) / (2 * sizeof(std::uint32_t))});
    out->chunks_ = gl::Buffer(sizeof(ChunkHeader) + out->chunk_capacity_ * 2 * sizeof(std::uint32_t), nullptr, true);
    // List entry i is vertices 4i .. 4i + 3, two triangles (0, 1, 2), (2, 1, 3): indexed, so the
    // two shared corners are shaded once (four vertex invocations a quad, not six).
    std::vector<std::uint32_t> indices(slots * 6);
    constexpr std::uint32_t kCorners[6] = {0, 1, 2, 2, 1, 3};
    for (size_t i = 0; i < slots; ++i)
      for (size_t k = 0; k < 6; ++k) indices[6 * i + k] = static_cast<std::uint32_t>(4 * i) + kCorners[k];
    out->indices_ = gl::Buffer::from<std::uint32_t>(indices);
    out->all_list_ = gl::Buffer::from<std::uint32_t>(all);
    DrawCommand every;
    every.count = static_cast<std::uint32_t>(6 * slots);
    out->all_command_ = gl::Buffer(sizeof every, &every, false);
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    out->vao_ = gl::GlHandle<gl::delete_vertex_array>(vao);
  }
  const SilhouetteStats& t = out->totals_;
  spdlog::info("esm: {} silhouette quads for {} edges of {} triangles ({} open, {} non-manifold, {} bevelled, "
               "{} degenerate triangles skipped; {} alpha-mask contour pieces, {} masked triangles too large to trace) built in {:.0f} ms",
               t.quads, t.edges, t.facets, t.open, t.non_manifold, t.beveled, t.degenerate_triangles, t.alpha_contours,
               t.alpha_skipped,
               std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  c.scene = gpu.serial();
  c.alpha_contours = options.alpha_contours;
  c.buffers = out;
  return out;
}

void SilhouetteBuffers::bind_records(const gl::Buffer& list) const {
  quads_.bind_base(GL_SHADER_STORAGE_BUFFER, SilhouetteBindings::quads);
  instances_.bind_base(GL_SHADER_STORAGE_BUFFER, SilhouetteBindings::instances);
  list.bind_base(GL_SHADER_STORAGE_BUFFER, SilhouetteBindings::list);
}

void SilhouetteBuffers::find(const gl::Program& program, const glm::vec4& light) const {
  if (instance_quads_ == 0) return;
  const FindCommand empty;
  glNamedBufferSubData(command_.id(), 0, sizeof empty, &empty);
  bind_records(list_);
  command_.bind_base(GL_SHADER_STORAGE_BUFFER, SilhouetteBindings::command);
  program.set("u_light", light);
  program.set("u_instance_count", static_cast<int>(instance_count_));
  program.set("u_instance_quads", static_cast<int>(instance_quads_));
  // One thread a quad of an instance; past 65535 groups a second dimension takes the rest.
  const size_t groups = (instance_quads_ + kFindGroupSize - 1) / kFindGroupSize;
  const GLuint gx = static_cast<GLuint>(std::min<size_t>(groups, 65535));
  const GLuint gy = static_cast<GLuint>((groups + gx - 1) / gx);
  glUseProgram(program.id());
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void SilhouetteBuffers::draw_found(const gl::Program& program) const { draw(program, list_, command_); }

void SilhouetteBuffers::bind_found() const {
  bind_records(list_);
  chunks_.bind_base(GL_SHADER_STORAGE_BUFFER, SilhouetteBindings::chunks);
}

void SilhouetteBuffers::reset_chunks() const {
  if (instance_quads_ == 0) return;
  ChunkHeader empty;
  empty.capacity = static_cast<std::uint32_t>(chunk_capacity_);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // after the previous face's passes
  glNamedBufferSubData(chunks_.id(), 0, sizeof empty, &empty);
}

void SilhouetteBuffers::draw_all(const gl::Program& program) const { draw(program, all_list_, all_command_); }

void SilhouetteBuffers::draw(const gl::Program& program, const gl::Buffer& list, const gl::Buffer& command) const {
  if (instance_quads_ == 0) return;
  bind_records(list);
  glUseProgram(program.id());
  glBindVertexArray(vao_.id());
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, command.id());
  glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
}

size_t SilhouetteBuffers::found() const {
  if (instance_quads_ == 0) return 0;
  FindCommand c;
  glGetNamedBufferSubData(command_.id(), 0, sizeof c, &c);
  return c.draw.count / 6;
}

std::array<std::uint32_t, 3> SilhouetteBuffers::write_groups() const {
  if (instance_quads_ == 0) return {0, 1, 1};
  FindCommand c;
  glGetNamedBufferSubData(command_.id(), 0, sizeof c, &c);
  return {c.write_groups, c.write_groups_y, c.write_groups_z};
}

}  // namespace penumbra::esm
