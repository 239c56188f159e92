// esm_silhouette_quads: this frame's silhouette quads drawn face by face into the extended
// shadow map (Bujnak, section 4.1): found first in a compute pass over every quad of every mesh
// instance, or, on small scenes, every quad drawn and collapsed in the vertex shader where it is
// no silhouette (silhouette_finding; the same map either way). blend = max: MAX blending, so where quads overlap
// the map keeps the farthest edge depth and the most shadowed edge value (the paper's "maximal
// depth, minimal distance"); the depth pass's neutral defaults make one pass enough. blend =
// overwrite: no blending, r and g replaced by whichever quad comes last: the first pass of the
// paper's two-pass fallback, for hardware without that blend mode, followed by a max pass.
#include <string>

#include "exec/gpu_scene.h"
#include "exec/pass_decl_builder.h"
#include "gl/framebuffer.h"
#include "techniques/esm/passes/esm_pass_common.h"
#include "techniques/esm/passes/esm_pass_types.h"
#include "techniques/esm/silhouette/silhouette_buffers.h"

namespace penumbra::esm {
namespace {

using graph::Format;

class SilhouetteQuadPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    if (!ctx.frame().scene) return {};
    auto buffers = SilhouetteBuffers::for_scene(*ctx.frame().scene);
    if (!buffers) return buffers.error();
    buffers_ = *buffers;  // keeps the shared buffers alive while this pass exists
    gl::ShaderProgram& find = ctx.program({.compute = "techniques/esm/shaders/silhouette_find.comp.glsl",
                                           .defines = silhouette_shader_defines()});
    if (!find.valid()) return *find.last_error();
    gl::ShaderProgram& p = ctx.program({.vertex = "techniques/esm/shaders/silhouette_quad.vert.glsl",
                                        .fragment = "techniques/esm/shaders/silhouette_quad.frag.glsl",
                                        .defines = silhouette_shader_defines()});
    if (!p.valid()) return *p.last_error();
    gl::Texture& esm = ctx.texture("esm");
    Result<EsmViews> views = frame_views(ctx, esm.width());
    if (!views) return views.error();
    if (attached_ != esm.id()) {
      fb_ = gl::Framebuffer();
      fb_.attach_color(0, esm);
      if (Status s = fb_.finish(); !s) return s;
      attached_ = esm.id();
    }
    const std::string& finding = ctx.enumeration("silhouette_finding");
    const bool find_first =
        finding == "gpu" || (finding == "auto" && buffers_->instance_quads() > kFindAboveQuads);
    if (find_first) buffers_->find(find.program(), views->light);  // one light: one list for every face
    const gl::Program& prog = p.program();
    set_view_uniforms(prog, *views);
    prog.set("u_light", views->light);
    prog.set("u_hidden_tolerance", ctx.real("hidden_edge_tolerance"));
    ctx.bind_sampled(p, "u_depth", "depth");
    fb_.bind();
    const bool max_blend = ctx.enumeration("blend") == "max";
    if (max_blend) {
      glEnablei(GL_BLEND, 0);
      glBlendEquationi(0, GL_MAX);  // the factors do not apply to MAX
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_SCISSOR_TEST);
    for (size_t i = 0; i < views->faces.size(); ++i) {
      const EsmFace& f = views->faces[i];
      prog.set("u_face", static_cast<int>(i));  // its texel size (esm_texel_world)
      glViewport(f.origin.x, f.origin.y, f.size, f.size);
      glScissor(f.origin.x, f.origin.y, f.size, f.size);
      prog.set("u_view_proj", f.view_proj);
      prog.set("u_inv_view_proj", glm::inverse(f.view_proj));
      prog.set("u_tile_size", static_cast<float>(f.size));
      prog.set("u_tile_origin", glm::vec2(f.origin));
      if (find_first) buffers_->draw_found(prog);
      else buffers_->draw_all(prog);
    }
    glDisable(GL_SCISSOR_TEST);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBlendEquationi(0, GL_FUNC_ADD);
    glDisablei(GL_BLEND, 0);
    return {};
  }

 private:
  std::shared_ptr<SilhouetteBuffers> buffers_;
  gl::Framebuffer fb_;
  GLuint attached_ = 0;
};

}  // namespace

exec::PassType silhouette_quad_pass_type() {
  exec::PassDeclBuilder b("esm_silhouette_quads");
  b.describe("Extended shadow map: silhouette quads of every mesh, MAX-blended or overwriting (raster)")
      .imported("scene")
      .imported("light")
      .sampled("depth", {Format::DEPTH32F})
      .same_size({"depth", "esm"})
      .enumeration("blend", "max", {"max", "overwrite"},
                   "max: MAX blending (one pass); overwrite: the two-pass fallback's first pass")
      .required()
      .enumeration("silhouette_finding", "auto", {"auto", "gpu", "all"},
                   "gpu: a compute pass lists the quads that are silhouettes from the light, and only those are drawn; "
                   "all: every quad is drawn and those that are none collapse in the vertex shader (the paper); "
                   "auto: gpu above " + std::to_string(kFindAboveQuads) +
                       " quads over all instances, where it pays. The map is the same")
      .real("hidden_edge_tolerance", 2.0, 0.0, 1000.0, "texels",
            "Hidden edges: an edge writes no texel whose surface is nearer the light than the edge (outside its "
            "occluder) or than its lit facet's plane (inside) by more than this many texel footprints");
  graph::PassTypeDecl decl = b.decl();
  decl.slots.push_back(blended_attachment("esm", Format::RG32F));
  return {decl, [] { return std::make_unique<SilhouetteQuadPass>(); }};
}

}  // namespace penumbra::esm
