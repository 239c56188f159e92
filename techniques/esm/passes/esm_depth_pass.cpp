// esm_depth: the extended shadow map's first pass (Bujnak, section 4: "rendering a depth map of
// the scene from the light point of view proceeds as in conventional shadow maps"), face by face:
// the casters' depth into the depth attachment with passes/shadow_map's program and biases
// (slope-scaled + constant polygon offset, alpha-tested casters), so that with the quads disabled
// the shadow test is plain shadow mapping; and the map's three channels (edge, edge_depth, edge_near) cleared to each texel's "no edge"
// values by a compute dispatch (esm_clear.comp.glsl says why not glClearTexImage). The map depth lives in the depth attachment only (the paper's green channel): the
// quads and the test read it there, and a depth-only raster pass costs no colour bandwidth.
#include "exec/gpu_scene.h"
#include "exec/pass_decl_builder.h"
#include "gl/framebuffer.h"
#include "passes/shadow_map/shadow_map_pass.h"
#include "techniques/esm/passes/esm_pass_common.h"
#include "techniques/esm/passes/esm_pass_types.h"

namespace penumbra::esm {
namespace {

using graph::Format;

class DepthPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    // Alpha-masked casters' quads follow the contour of the mask's nearest texels (alpha_contours.h):
    // the depth map tests them the same way, or the two disagree along every contour.
    std::vector<std::pair<std::string, std::string>> defines;
    if (ctx.boolean("alpha_contours")) defines.emplace_back("ALPHA_TEST_NEAREST_TEXEL", "1");
    gl::ShaderProgram& p = ctx.program({.vertex = "passes/shadow_map/shadow_map.vert.glsl",
                                        .fragment = "passes/shadow_map/shadow_map.frag.glsl",
                                        .defines = defines});
    if (!p.valid()) return *p.last_error();
    gl::ShaderProgram& clear = ctx.program({.compute = "techniques/esm/shaders/esm_clear.comp.glsl"});
    if (!clear.valid()) return *clear.last_error();
    gl::Texture& depth = ctx.texture("depth");
    gl::Texture& edge = ctx.texture("edge");
    Result<EsmViews> views = frame_views(ctx, edge.width());
    if (!views) return views.error();
    if (attached_ != depth.id()) {
      fb_ = gl::Framebuffer();
      fb_.attach_depth(depth);
      if (Status s = fb_.finish(); !s) return s;
      attached_ = depth.id();
    }
    // A texel no quad reaches (esm_common.glsl): r and g neutral for MAX blending (0), or the
    // paper's defaults for its two-pass fallback (lit-ness 0.75 -> r = 0.25, "maximal distance"
    // g = 1), which the fallback's first quad pass overwrites; r below QUAD_MARK: no quad.
    const bool two_pass = ctx.enumeration("overlap_resolve") == "two_pass";
    const glm::vec2 no_edge(two_pass ? 0.25f : 0.0f, two_pass ? 1.0f : 0.0f);
    ctx.bind_image(0, "edge", GL_WRITE_ONLY);
    ctx.bind_image(1, "edge_depth", GL_WRITE_ONLY);
    ctx.bind_image(2, "edge_near", GL_WRITE_ONLY);
    clear.program().set("u_value", no_edge);
    ctx.dispatch_over(clear, edge);
    // The quad passes blend into the map as colour attachments or MAX into it by image atomics:
    // make the image stores visible to either (the graph plans barriers by the slots' declared
    // use, attachments, so this pass adds the one its compute clear needs).
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    if (!ctx.frame().scene) {
      depth.clear(1.0f);
      return {};
    }
    passes::render_depth_faces(fb_, p.program(), *ctx.frame().scene, views->faces, ctx.real("slope_bias"),
                               ctx.real("constant_bias"));
    return {};
  }

 private:
  gl::Framebuffer fb_;
  GLuint attached_ = 0;
};

}  // namespace

exec::PassType depth_pass_type() {
  return exec::PassDeclBuilder("esm_depth")
      .describe("Extended shadow map, depth pass: depth (polygon offset) of every face; edge, edge depth and nearest edge cleared to 'no edge' (raster)")
      .imported("scene")
      .imported("light")
      .depth_out("depth")
      .color_out("edge", {Format::R32F})
      .color_out("edge_depth", {Format::R32F})
      .color_out("edge_near", {Format::R32F})
      .same_size({"depth", "edge", "edge_depth", "edge_near"})
      .real("slope_bias", 1.5, 0.0, 10.0, "", "Depth pass slope-scaled bias (glPolygonOffset factor)")
      .real("constant_bias", 2.0, 0.0, 1000.0, "depth steps", "Depth pass constant bias (glPolygonOffset units)")
      .boolean("alpha_contours", false,
               "Alpha-masked casters tested at the nearest texel of the texture's full-resolution level, as the "
               "silhouette quads trace their contours; false: the filtered alpha of every shadow map")
      .enumeration("overlap_resolve", "max_blend", {"max_blend", "two_pass"},
                   "Overlapping quads: one MAX-blended pass, or the paper's fallback (an overwriting pass, then a MAX "
                   "pass); the depth pass clears the map for the one chosen")
      .build<DepthPass>();
}

}  // namespace penumbra::esm
