#pragma once
// CompiledPlan: everything an executor needs to run one frame of a graph, with no GL in it.
// The executor walks `passes` in order: issues `barriers` (glMemoryBarrier bits), binds each
// binding's physical resource, sets parameters (reading "$param" references from the live
// ParameterSet every frame; constants are resolved), and dispatches the pass type's code.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "graph/pass_types.h"
#include "graph/resources.h"

namespace penumbra::graph {

// GL-free memory barrier bits; the executor maps them to GL_*_BARRIER_BIT.
enum BarrierBit : std::uint32_t {
  barrier_none = 0,
  barrier_texture_fetch = 1u << 0,         // sampling after an image/buffer store
  barrier_shader_image_access = 1u << 1,   // image load/store after an image store
  barrier_framebuffer = 1u << 2,           // attachment use after an image store
  barrier_storage_buffer = 1u << 3,        // SSBO access after an SSBO write
  barrier_texture_update = 1u << 4,        // reserved for uploads/readbacks
  barrier_command = 1u << 5,               // indirect arguments after an SSBO write
};
std::string barrier_bits_to_string(std::uint32_t bits);  // "texture_fetch|framebuffer"

struct CompileOptions {
  bool no_reuse = false;            // debug: one physical resource per resource version group
  bool extended_lifetimes = false;  // debug: every transient lives the whole frame
  std::vector<std::string> keep_alive;  // resources kept to the end of the frame (viewer)
};

// One physical texture or buffer the executor creates (imported resources have none).
struct PhysicalResource {
  int id = 0;
  ResourceKind kind = ResourceKind::texture;  // texture, buffer or persistent
  Format format = Format::RGBA8;
  int width = 0, height = 0;   // texels
  std::uint64_t bytes = 0;     // total size in bytes
  std::vector<std::string> holds;  // "name@version" it holds over the frame, in order
};

// One version of one logical resource.
struct ResourceVersion {
  std::string name;
  int version = 0;
  ResourceKind kind = ResourceKind::texture;
  int physical = -1;       // PhysicalResource id; -1 for imported
  int producer = -1;       // index into CompiledPlan::passes; -1 = from outside the frame
  int first_use = 0;       // pass index range [first_use, last_use] in which it must live
  int last_use = 0;        // == passes.size() when it lives to the end of the frame
  std::string label() const { return name + "@" + std::to_string(version); }
};

struct PlannedBinding {
  std::string slot;
  Access access = Access::read;
  Usage usage = Usage::sampled;
  std::string resource;
  int read_version = -1;   // -1 when the slot only writes
  int write_version = -1;  // -1 when the slot only reads
  int physical = -1;       // -1 for imported
  int tiled_width = 0, tiled_height = 0;  // a tile list: the area its tiles cut, pixels
};

struct PlannedParam {
  std::string name;
  ParamValue value;       // resolved constant (or the parameter's value at compile time)
  std::string reference;  // technique parameter name when given as "$name": read per frame
};

// Bytes a pass moves through memory in one execution, by the model of traffic.cpp (the
// resources it binds, each counted once at its size; docs/graph-format.md "Traffic").
struct PassTraffic {
  std::uint64_t read_bytes = 0;
  std::uint64_t written_bytes = 0;
  std::uint64_t total() const { return read_bytes + written_bytes; }
};

struct PlannedPass {
  std::string type;
  std::string name;        // instance name; repetitions are "name[i]"
  std::string declared_as; // the declaration's name
  int iteration = 0;       // 0..repeat-1
  bool frame = false;      // one of the frame's own passes (G-buffer, lighting), not a technique's
  std::vector<PlannedBinding> bindings;
  std::vector<PlannedParam> params;
  std::uint32_t barriers = barrier_none;  // issue before the pass
  std::vector<std::string> barrier_reasons;  // "shadow_mask@1: texture_fetch"
  PassTraffic traffic;                       // per execution (each repetition is a pass)
};

struct MemoryReport {
  std::uint64_t naive_bytes = 0;     // one physical resource per version group
  std::uint64_t assigned_bytes = 0;  // after reuse
};

struct CompiledPlan {
  std::string graph_name;
  CompileSettings settings;
  CompileOptions options;
  std::vector<PlannedPass> passes;          // execution order
  std::vector<std::string> culled;          // enabled passes that reach no output
  std::vector<std::string> disabled;        // passes whose `enabled` was false
  std::vector<PhysicalResource> physical;
  std::vector<ResourceVersion> versions;    // of the passes that run
  std::map<std::string, int> physical_of;   // logical name -> physical of its final version
  std::vector<std::string> outputs;
  MemoryReport memory;

  // Physical id of `name` (final version, or version v); -1 when absent or imported.
  int physical_for(const std::string& name, int version = -1) const;
};

// Deterministic text dump (golden files), Graphviz, and JSON (every pass with its bindings,
// parameters and traffic; the physical resources; memory).
std::string to_text(const CompiledPlan& plan);
std::string to_dot(const CompiledPlan& plan);
std::string to_json(const CompiledPlan& plan);

// The bytes `pass` reads and writes: every binding's physical resource once at its full size
// (read if the slot reads, written if it writes; a depth attachment the pass writes is also
// read, by the depth test). Imported resources (scene geometry, camera, light) count nothing.
// A pass that dispatches over a tile list, measured to have run `tile_fraction` of the list's
// capacity (bench reads the count back), moves that share of each screen-sized texture and of
// the list; everything else whole. The plan itself counts every tile (fraction 1).
PassTraffic pass_traffic(const CompiledPlan& plan, const PlannedPass& pass, double tile_fraction = 1.0);

// The tile list `pass` dispatches over (Usage::indirect_dispatch), or nullptr.
const PlannedBinding* dispatch_tile_list(const PlannedPass& pass);

// `penumbra graph --traffic`: pass, read MB, written MB, bytes per screen pixel; totals for the
// technique's passes and for the whole frame. MB = 10^6 bytes.
std::string traffic_table(const CompiledPlan& plan);

}  // namespace penumbra::graph
