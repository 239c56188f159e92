// esm_mask: the shadow test of the extended shadow map (Bujnak, section 3.2) into the frame's
// shadow_mask (compute; shaders/esm_mask.comp.glsl says how the lookup decides).
#include <glm/gtc/matrix_inverse.hpp>

#include "exec/pass_decl_builder.h"
#include "gl/texture.h"
#include "passes/common/shadow_receiver_decl.h"
#include "passes/common/shadow_uniforms.h"
#include "techniques/esm/passes/esm_pass_common.h"
#include "techniques/esm/passes/esm_pass_types.h"

namespace penumbra::esm {
namespace {

using graph::Format;

class MaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/esm/shaders/esm_mask.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    Result<EsmViews> views = frame_views(ctx, ctx.texture("edge").width());
    if (!views) return views.error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map");
    if (nearest_.id() == 0) nearest_ = gl::Sampler(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp);
    ctx.bind_sampled(p, "u_edge", "edge", nearest_.id());  // texel fetches and one gather
    ctx.bind_sampled(p, "u_edge_depth", "edge_depth", nearest_.id());
    ctx.bind_sampled(p, "u_edge_near", "edge_near", nearest_.id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    const gl::Program& prog = p.program();
    if (Status s = passes::set_shadow_uniforms(prog, ctx.frame(), passes::SixFaces::read); !s) return s;  // faces_away_from_light()
    set_view_uniforms(prog, *views);
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    prog.set("u_boundary_shift", ctx.real("boundary_shift"));
    prog.set("u_aa_width", ctx.real("aa_width"));
    prog.set("u_edge_bias_texels", ctx.real("edge_bias"));
    prog.set("u_nearest_edge", ctx.boolean("nearest_edge") ? 1 : 0);
    prog.set("u_edge_lines", ctx.boolean("edge_lines") ? 1 : 0);
    prog.set("u_edge_plane", ctx.boolean("edge_plane") ? 1 : 0);
    prog.set("u_inv_view_proj", glm::inverse(ctx.frame().projection() * ctx.frame().view()));
    gl::Texture& mask = ctx.texture("mask");
    prog.set("u_screen", glm::vec2(mask.width(), mask.height()));
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }

 private:
  gl::Sampler nearest_;
};

}  // namespace

exec::PassType mask_pass_type() {
  return passes::shadow_receiver_pass(
             "esm_mask", "Extended shadow map test: point-filtered depth and edge depths, the edge distance from the texels' edge lines (compute)")
      .sampled("edge", {Format::R32F})
      .sampled("edge_depth", {Format::R32F})
      .sampled("edge_near", {Format::R32F})
      .image_out("mask", {Format::R16F})
      .same_size({"depth", "normal", "mask"})
      .same_size({"shadow_map", "edge", "edge_depth", "edge_near"})
      .real("depth_bias", 0.0005, 0.0, 0.05, "window depth",
            "Subtracted from the receiver depth before the depth and edge-depth comparisons")
      .real("aa_width", 1.0, 0.0, 8.0, "pixels", "Width of the shadow edge's ramp on screen: 1 = the pixel's coverage; 0 = binary")
      .real("boundary_shift", 0.0, 0.0, 2.0, "texels", "Shadow boundary moved outwards from the silhouette edge (the paper: 0.707)")
      .real("edge_bias", 0.1, 0.0, 8.0, "texels",
            "A receiver is behind a silhouette edge when deeper than the edge by more than its own depth change over this "
            "many texels; nearer receivers get the plain test")
      .boolean("edge_plane", true,
               "A receiver is behind a texel's edge line only where its tangent plane, extended to the line, is behind the "
               "edge too (a surface running into its own edge is not shadowed by it); false: the depth margin edge_bias "
               "alone (0.5 texels was its default then)")
      .boolean("nearest_edge", true,
               "A receiver not behind a texel's farthest edge (its own, at a contact) but behind its nearest one uses that "
               "edge alone; false: the plain test there, as before the map kept the nearest edge")
      .boolean("edge_lines", true,
               "The receiver's distance from the silhouette from the footprint texels' edges as lines (the nearest texel's, "
               "combined at corners); false: bilinear interpolation of the texels' distances (the paper)")
      .build<MaskPass>();
}

}  // namespace penumbra::esm
