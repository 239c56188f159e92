// esm_silhouette_quads: this frame's silhouette quads written face by face into the extended
// shadow map's three channels (Bujnak, section 4.1), in one of three ways (silhouette_finding; the
// same map every way): every quad drawn and collapsed in the vertex shader where it is no
// silhouette (the paper's, cheapest on small scenes); the silhouettes found first by a compute
// pass over every quad of every mesh instance, and only they drawn; or found, then written texel
// by texel by a compute pass with image atomics, without the raster.
// blend = max: MAX blending (or atomic MAX), so where quads overlap the map keeps the farthest
// edge depth and the edge key's choice (an inside over an outside, the nearest edge on either
// side), and the nearest edge in depth with its own value (esm_common.glsl; by image atomics on either path);
// the depth pass's neutral defaults make one pass enough. blend = overwrite: no blending, edge
// and edge depth replaced by whichever quad comes last (the nearest edge still by atomic MAX):
// the first pass of the paper's two-pass fallback, for hardware without that blend mode,
// followed by a max pass; it always draws.
#include <string>
#include <utility>
#include <vector>

#include <spdlog/spdlog.h>

#include "exec/gpu_scene.h"
#include "exec/pass_decl_builder.h"
#include "gl/framebuffer.h"
#include "techniques/esm/passes/esm_pass_common.h"
#include "techniques/esm/passes/esm_pass_types.h"
#include "techniques/esm/silhouette/silhouette_buffers.h"

namespace penumbra::esm {
namespace {

using graph::Format;

// How this pass's quads reach the map this frame.
enum class Writing { draw_all, draw_found, compute };

class SilhouetteQuadPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    if (!ctx.frame().scene) return {};
    auto buffers = SilhouetteBuffers::for_scene(*ctx.frame().scene, {.alpha_contours = ctx.boolean("alpha_contours")});
    if (!buffers) return buffers.error();
    buffers_ = *buffers;  // keeps the shared buffers alive while this pass exists
    if (buffers_->instance_quads() == 0) return {};  // no caster edges: the map stays "no edge"
    gl::Texture& edge = ctx.texture("edge");
    Result<EsmViews> views = frame_views(ctx, edge.width());
    if (!views) return views.error();
    const Writing writing = choose_writing(ctx);
    if (writing != Writing::draw_all) {
      gl::ShaderProgram& find = ctx.program({.compute = "techniques/esm/shaders/silhouette_find.comp.glsl",
                                             .defines = silhouette_shader_defines()});
      if (!find.valid()) return *find.last_error();
      buffers_->find(find.program(), views->light);  // one light: one list for every face
    }
    // The nearest edge is MAXed by image atomics whichever way the quads are written (an image
    // slot: the graph plans its barriers).
    ctx.bind_image_bits(2, "edge_near", GL_READ_WRITE);
    if (writing == Writing::compute) return write(ctx, *views);
    return draw(ctx, *views, writing);
  }

 private:
  Writing choose_writing(const exec::PassContext& ctx) {
    const std::string finding = ctx.enumeration("silhouette_finding");
    const bool max_blend = ctx.enumeration("blend") == "max";
    // Overwriting has no order among atomics: the two-pass fallback's first pass always draws.
    const bool compute_pays =
        buffers_->instance_quads() > kComputeAboveQuads || ctx.texture("edge").width() >= kComputeFromMapSize;
    if (finding == "compute" || (finding == "auto" && compute_pays)) {
      if (max_blend && buffers_->can_write_found()) return Writing::compute;
      if (max_blend && !warned_) {
        spdlog::warn("esm: {} silhouette quads over the scene's instances are more work groups than this GL "
                     "dispatches at once; drawing them instead of writing them by compute",
                     buffers_->instance_quads());
        warned_ = true;
      }
      return Writing::draw_found;
    }
    return finding == "gpu" ? Writing::draw_found : Writing::draw_all;
  }

  // The listed quads' texels by compute, face by face, atomic MAX into the three channels: per face a
  // pass over the listed quads that writes the short ones and lists the chunks of the long ones,
  // then a pass over those chunks (shaders/silhouette_write.comp.glsl).
  Status write(exec::PassContext& ctx, const EsmViews& views) {
    const std::vector<std::pair<std::string, std::string>> defines = silhouette_shader_defines();
    std::vector<std::pair<std::string, std::string>> listing = defines;
    listing.emplace_back("LIST_CHUNKS", "1");
    const char* source = "techniques/esm/shaders/silhouette_write.comp.glsl";
    gl::ShaderProgram& quads = ctx.program({.compute = source, .defines = listing});
    if (!quads.valid()) return *quads.last_error();
    gl::ShaderProgram& chunks = ctx.program({.compute = source, .defines = defines});
    if (!chunks.valid()) return *chunks.last_error();
    for (gl::ShaderProgram* p : {&quads, &chunks}) {
      set_quad_uniforms(ctx, p->program(), views);
      ctx.bind_sampled(*p, "u_depth", "depth");
    }
    ctx.bind_image_bits(0, "edge", GL_READ_WRITE);
    ctx.bind_image_bits(1, "edge_depth", GL_READ_WRITE);
    buffers_->bind_found();
    for (size_t i = 0; i < views.faces.size(); ++i) {
      set_face_uniforms(quads.program(), views, i);
      set_face_uniforms(chunks.program(), views, i);
      buffers_->reset_chunks();
      ctx.dispatch_indirect(quads, buffers_->command(), SilhouetteBuffers::kWriteCommandOffset);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
      ctx.dispatch_indirect(chunks, buffers_->chunks(), SilhouetteBuffers::kChunkDispatchOffset);
    }
    // The graph plans barriers by the slots' declared use (attachments): the mask's fetches and a
    // later raster pass must see the image atomics.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    return {};
  }

  Status draw(exec::PassContext& ctx, const EsmViews& views, Writing writing) {
    gl::ShaderProgram& p = ctx.program({.vertex = "techniques/esm/shaders/silhouette_quad.vert.glsl",
                                        .fragment = "techniques/esm/shaders/silhouette_quad.frag.glsl",
                                        .defines = silhouette_shader_defines()});
    if (!p.valid()) return *p.last_error();
    gl::Texture& edge = ctx.texture("edge");
    gl::Texture& edge_depth = ctx.texture("edge_depth");
    // The pool may hand either channel another texture in a new plan: rebuild when either moved.
    if (attached_ != std::pair(edge.id(), edge_depth.id())) {
      fb_ = gl::Framebuffer();
      fb_.attach_color(0, edge);
      fb_.attach_color(1, edge_depth);
      if (Status s = fb_.finish(); !s) return s;
      attached_ = {edge.id(), edge_depth.id()};
    }
    const gl::Program& prog = p.program();
    set_quad_uniforms(ctx, prog, views);
    ctx.bind_sampled(p, "u_depth", "depth");
    fb_.bind();
    const bool max_blend = ctx.enumeration("blend") == "max";
    if (max_blend) {
      for (GLuint target : {0u, 1u}) {
        glEnablei(GL_BLEND, target);
        glBlendEquationi(target, GL_MAX);  // the factors do not apply to MAX
      }
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_SCISSOR_TEST);
    for (size_t i = 0; i < views.faces.size(); ++i) {
      const EsmFace& f = views.faces[i];
      glViewport(f.origin.x, f.origin.y, f.size, f.size);
      glScissor(f.origin.x, f.origin.y, f.size, f.size);
      set_face_uniforms(prog, views, i);
      if (writing == Writing::draw_found) buffers_->draw_found(prog);
      else buffers_->draw_all(prog);
    }
    glDisable(GL_SCISSOR_TEST);
    for (GLuint target : {0u, 1u}) {
      glBlendEquationi(target, GL_FUNC_ADD);
      glDisablei(GL_BLEND, target);
    }
    return {};
  }

  static void set_quad_uniforms(const exec::PassContext& ctx, const gl::Program& prog, const EsmViews& views) {
    set_view_uniforms(prog, views);
    prog.set("u_light", views.light);
    prog.set("u_hidden_tolerance", ctx.real("hidden_edge_tolerance"));
  }

  static void set_face_uniforms(const gl::Program& prog, const EsmViews& views, size_t i) {
    const EsmFace& f = views.faces[i];
    prog.set("u_face", static_cast<int>(i));  // its texel size (esm_texel_world)
    prog.set("u_view_proj", f.view_proj);
    prog.set("u_inv_view_proj", glm::inverse(f.view_proj));
    prog.set("u_tile_size", static_cast<float>(f.size));
    prog.set("u_tile_origin", glm::vec2(f.origin));
  }

  std::shared_ptr<SilhouetteBuffers> buffers_;
  gl::Framebuffer fb_;
  std::pair<GLuint, GLuint> attached_{0, 0};  // the edge and edge_depth textures fb_ holds
  bool warned_ = false;
};

}  // namespace

exec::PassType silhouette_quad_pass_type() {
  exec::PassDeclBuilder b("esm_silhouette_quads");
  b.describe("Extended shadow map: silhouette quads of every mesh, MAX-blended or overwriting (raster), or atomic MAX (compute)")
      .imported("scene")
      .imported("light")
      .sampled("depth", {Format::DEPTH32F})
      .image_inout("edge_near", {Format::R32F})  // image atomics, from either path
      .same_size({"depth", "edge", "edge_depth", "edge_near"})
      .enumeration("blend", "max", {"max", "overwrite"},
                   "max: MAX blending (one pass); overwrite: the two-pass fallback's first pass")
      .required()
      .enumeration("silhouette_finding", "auto", {"auto", "gpu", "compute", "all"},
                   "gpu: a compute pass lists the quads that are silhouettes from the light, and only those are drawn; "
                   "compute: listed as for gpu, then written texel by texel by a compute pass (image atomics, no "
                   "raster; blend=overwrite draws them); all: every quad is drawn and those that are none collapse "
                   "in the vertex shader (the paper); auto: compute above " + std::to_string(kComputeAboveQuads) +
                       " quads over all instances or on maps " + std::to_string(kComputeFromMapSize) +
                       " texels wide and wider, where it pays, else all. The map is the same")
      .real("hidden_edge_tolerance", 2.0, 0.0, 1000.0, "texels",
            "Hidden edges: an edge writes no texel whose surface is nearer the light than the edge (outside its "
            "occluder) or than its lit facet's plane (inside) by more than this many texel footprints")
      .boolean("alpha_contours", true,
               "Alpha-masked casters get quads along their mask's contour (traced in the texture at load); false: "
               "none, their shadows are the plain map's");
  graph::PassTypeDecl decl = b.decl();
  decl.slots.push_back(blended_attachment("edge", Format::R32F));
  decl.slots.push_back(blended_attachment("edge_depth", Format::R32F));
  return {decl, [] { return std::make_unique<SilhouetteQuadPass>(); }};
}

}  // namespace penumbra::esm
