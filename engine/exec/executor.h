#pragma once
// Runs a CompiledPlan every frame: takes physical textures from the pool, issues the planned
// memory barriers, binds, runs each pass's GL code and times it.
//
//   exec::Executor executor(library, shaders, pool);
//   if (Status s = executor.set_plan(std::move(*plan)); !s) report(s.error());
//   for (;;) {
//     if (Status s = executor.execute(params, frame); !s) report(s.error());
//     const gl::Texture* mask = executor.resource("shadow_mask");   // for a viewer
//   }
//
// Debug switches (Unreal RDG style, each turns one clever part off): no reuse and extended
// lifetimes are compile options (graph::CompileOptions); immediate mode is here: glFinish and a
// glGetError check after every pass, so the failing pass is named.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "exec/frame_inputs.h"
#include "exec/pass.h"
#include "exec/pass_timer.h"
#include "exec/shader_cache.h"
#include "exec/texture_pool.h"
#include "graph/plan.h"

namespace penumbra::exec {

struct ExecutorOptions {
  bool immediate = false;
  // Automatic: timestamps on a GPU, glFinish + CPU clock on a software renderer.
  bool timing_enabled = true;
  // Tests: force a timing mode (e.g. timestamps on llvmpipe, to exercise the query queue).
  std::optional<TimingMode> force_timing_mode;
};

class Executor {
 public:
  Executor(const PassLibrary& library, ShaderCache& shaders, TexturePool& pool)
      : library_(library), shaders_(shaders), pool_(pool) {}

  // Creates the passes' implementations and acquires physical textures. On error the previous
  // plan stays in place.
  Status set_plan(graph::CompiledPlan plan);
  bool has_plan() const { return has_plan_; }
  const graph::CompiledPlan& plan() const { return plan_; }

  Status execute(const graph::ParameterSet& params, const FrameInputs& frame);

  // The texture holding a logical resource's final version (nullptr when absent or imported).
  // Keep a resource listed in CompileOptions::keep_alive to be sure no later pass reuses it.
  gl::Texture* resource(const std::string& name) const;
  gl::Texture* physical_texture(int id) const;
  gl::Buffer* physical_buffer(int id) const;
  std::vector<std::string> resource_names() const;
  // Whether the pass at `index` of the plan ran over a tile list in the last frame.
  bool dispatched_over_tiles(size_t index) const { return index < over_tiles_.size() && over_tiles_[index]; }

  ExecutorOptions& options() { return options_; }
  const std::vector<PassTiming>& timings() const { return timer_.timings(); }
  // Waits for the GPU timings still in flight (benchmarks call this before reading timings()).
  void flush_timings() { timer_.flush(); }
  TimingMode timing_mode() const { return timer_.mode(); }
  std::uint32_t frames_executed() const { return frames_; }
  // The last progress a pass of this plan reported (exec/pass_progress.h); none before one did.
  const std::optional<PassProgress>& progress() const { return progress_; }

 private:
  const PassLibrary& library_;
  ShaderCache& shaders_;
  TexturePool& pool_;
  ExecutorOptions options_;
  graph::CompiledPlan plan_;
  bool has_plan_ = false;
  std::vector<std::unique_ptr<PassImpl>> impls_;
  std::vector<gl::Texture*> textures_;  // by physical id
  std::vector<gl::Buffer*> buffers_;    // by physical id
  gl::Buffer frame_uniforms_;           // exec/frame_uniforms.h, refreshed every frame
  PassTimer timer_;
  std::uint32_t frames_ = 0;
  std::optional<PassProgress> progress_;
  std::vector<char> over_tiles_;  // by pass index, the last frame
};

GLbitfield gl_barrier_bits(std::uint32_t graph_bits);

}  // namespace penumbra::exec
