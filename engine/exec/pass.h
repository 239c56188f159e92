#pragma once
// The contract between the render graph and a pass's GL code.
//
// A pass type is a GL-free declaration (graph::PassTypeDecl: slots, parameters) plus a factory
// of PassImpl objects. The executor creates one PassImpl per planned pass when a plan is set,
// so an implementation may keep GL objects (framebuffers, VAOs) across frames, and calls
// execute() every frame with a PassContext that resolves slot names to textures and parameter
// names to their current values.
//
//   class InvertPass final : public exec::PassImpl {
//     Status execute(exec::PassContext& ctx) override {
//       gl::ShaderProgram& p = ctx.program({.compute = "passes/invert/invert.comp.glsl"});
//       if (!p.valid()) return p.last_error().value();
//       ctx.bind_sampled(p, "src", "input");           // texture unit + uniform
//       ctx.bind_image(0, "output", GL_WRITE_ONLY);     // image unit 0
//       p.program().set("strength", ctx.real("strength"));
//       ctx.dispatch_over(p, ctx.texture("output"));      // one thread per texel
//       return {};
//     }
//   };
//   library.add({.decl = {...}, .create = [] { return std::make_unique<InvertPass>(); }});
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "exec/frame_inputs.h"
#include "exec/pass_progress.h"
#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "graph/parameters.h"
#include "graph/pass_types.h"
#include "graph/plan.h"

namespace penumbra::exec {

class ShaderCache;

class PassContext {
 public:
  PassContext(const graph::PlannedPass& pass, const graph::ParameterSet& params, const FrameInputs& frame,
              ShaderCache& shaders, std::function<gl::Texture*(int)> textures,
              std::function<gl::Buffer*(int)> buffers, std::optional<PassProgress>* progress)
      : pass_(pass), params_(params), frame_(frame), shaders_(shaders),
        textures_(std::move(textures)), buffers_(std::move(buffers)), progress_(progress) {}

  const graph::PlannedPass& pass() const { return pass_; }
  const FrameInputs& frame() const { return frame_; }

  bool bound(std::string_view slot) const;
  // The texture bound to `slot`; throws std::logic_error naming pass and slot when unbound
  // (a declaration bug, caught by the executor and reported as an Error).
  gl::Texture& texture(std::string_view slot) const;
  gl::Buffer& buffer(std::string_view slot) const;

  // Current parameter values: "$name" bindings read the live technique parameters, so a
  // non-structural change takes effect next frame without recompiling.
  bool boolean(std::string_view name) const;
  int integer(std::string_view name) const;
  float real(std::string_view name) const;
  std::string enumeration(std::string_view name) const;

  // Programs are cached by sources+defines and hot-reloaded by the ShaderCache. A frame whose
  // light needs six faces (frame().shadow.six_faces) gets the variant with SIX_FACES defined
  // (passes/common/shadow_common.glsl), so one-view frames compile none of that code. Sources
  // that define SIX_FACES themselves (a pass that renders faces of its own) are taken as given.
  // A frame with cascades (frame().cascades.count > 1) gets CASCADES defined as their count.
  gl::ShaderProgram& program(const gl::ShaderSources& sources);

  // Binding helpers (texture units are allocated per call sequence within one pass).
  void bind_sampled(const gl::ShaderProgram& p, const char* uniform, std::string_view slot,
                    GLuint sampler = 0);
  void bind_image(GLuint unit, std::string_view slot, GLenum access, int level = 0) const;
  // An R32F slot's storage bound as r32ui, for imageAtomicMax: the bit patterns of non-negative
  // floats order as their values do, so the atomic MAX of the bits is the MAX of the floats.
  void bind_image_bits(GLuint unit, std::string_view slot, GLenum access) const;
  // One thread per texel of `target`, rounded up to the program's local size.
  void dispatch_over(const gl::ShaderProgram& p, int width, int height) const;
  void dispatch_over(const gl::ShaderProgram& p, const gl::Texture& target) const {
    dispatch_over(p, target.width(), target.height());
  }
  // One workgroup per tile x tile block of a width x height target, for shaders whose
  // workgroup is larger than the block it writes (it also computes a halo around it).
  void dispatch_tiles(const gl::ShaderProgram& p, int width, int height, int tile) const;

  // Tile lists (graph/resources.h; engine/gl/shaders/tile_list.glsl). The writer empties the
  // list it fills (no tiles, dispatch arguments 0 x 1 x 1) and binds it as a storage buffer; the
  // reader binds it at the same binding and runs one work group per appended tile, the count
  // taken by the GPU from the list's header (indirect dispatch: no read-back).
  void reset_tile_list(std::string_view slot) const;
  void bind_tile_list(GLuint binding, std::string_view slot) const;
  void dispatch_over_tiles(const gl::ShaderProgram& p, std::string_view slot) const;
  // Work groups counted by an earlier GPU pass of the pass's own (glDispatchComputeIndirect's
  // three counts at `offset` in `command`).
  void dispatch_indirect(const gl::ShaderProgram& p, const gl::Buffer& command, GLintptr offset) const;

  // Set when a dispatch was refused: an image bound to a unit whose declared format qualifier
  // differs from the texture's format (the executor reports it as the pass's error).
  const std::optional<Error>& binding_error() const { return binding_error_; }
  // Whether this execution dispatched over a tile list (a pass with one bound may still run
  // over every pixel, e.g. the first of a repeated pass).
  bool dispatched_over_tiles() const { return dispatched_over_tiles_; }

  // A progressive pass's progress (exec/pass_progress.h); the executor keeps the last report.
  void report_progress(PassProgress progress) const {
    if (progress_) *progress_ = std::move(progress);
  }

 private:
  const graph::PlannedBinding* find(std::string_view slot) const;
  const graph::ParamValue& value(std::string_view name) const;
  // False (and binding_error() set) when an image bound for this dispatch has another format
  // than `p` declares for its unit.
  bool images_match(const gl::ShaderProgram& p) const;

  const graph::PlannedPass& pass_;
  const graph::ParameterSet& params_;
  const FrameInputs& frame_;
  ShaderCache& shaders_;
  std::function<gl::Texture*(int)> textures_;
  std::function<gl::Buffer*(int)> buffers_;
  std::optional<PassProgress>* progress_;
  GLuint next_unit_ = 0;
  struct BoundImage {
    GLuint unit;
    std::string slot;
    graph::Format format;
    std::string_view qualifier;  // what the shader must declare at the unit
  };
  mutable std::vector<BoundImage> images_;
  mutable std::optional<Error> binding_error_;
  mutable bool dispatched_over_tiles_ = false;
};

class PassImpl {
 public:
  virtual ~PassImpl() = default;
  virtual Status execute(PassContext& ctx) = 0;
};

struct PassType {
  graph::PassTypeDecl decl;
  std::function<std::unique_ptr<PassImpl>()> create;
};

// Every pass type the executor can run; its declarations form the compiler's registry.
class PassLibrary {
 public:
  void add(PassType type);
  const PassType* find(std::string_view name) const;
  const graph::PassTypeRegistry& declarations() const { return declarations_; }

 private:
  std::map<std::string, PassType, std::less<>> types_;
  graph::PassTypeRegistry declarations_;
};

}  // namespace penumbra::exec
