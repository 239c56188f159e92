// esm_debug: the edge-distance channel (texels) and the silhouette mask of the extended shadow
// map as single-channel textures, for the sandbox viewer and the tests (compute).
#include "exec/pass_decl_builder.h"
#include "techniques/esm/passes/esm_pass_types.h"

namespace penumbra::esm {
namespace {

using graph::Format;

class DebugPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/esm/shaders/esm_debug.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_edge", "edge");
    ctx.bind_image(0, "edge_distance", GL_WRITE_ONLY);
    ctx.bind_image(1, "silhouette_mask", GL_WRITE_ONLY);
    ctx.dispatch_over(p, ctx.texture("edge_distance"));
    return {};
  }
};

}  // namespace

exec::PassType debug_pass_type() {
  return exec::PassDeclBuilder("esm_debug")
      .describe("Extended shadow map debug views: edge distance (texels) and silhouette mask (compute)")
      .sampled("edge", {Format::R32F})
      .image_out("edge_distance", {Format::R32F})
      .image_out("silhouette_mask", {Format::R16F})
      .same_size({"edge", "edge_distance", "silhouette_mask"})
      .build<DebugPass>();
}

}  // namespace penumbra::esm
