// G-buffer pre-pass: the frame's first pass (technique/frame_graph.h). A raster pass: depth,
// world normal, world position with linear view depth, and base colour for the lighting pass.
#include "passes/gbuffer/gbuffer_pass.h"

#include "exec/gpu_scene.h"
#include "exec/pass_decl_builder.h"
#include "gl/framebuffer.h"

namespace penumbra::passes {
namespace {

using graph::Format;

class GBufferPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.vertex = "passes/gbuffer/gbuffer.vert.glsl",
                                        .fragment = "passes/gbuffer/gbuffer.frag.glsl"});
    if (!p.valid()) return *p.last_error();
    gl::Texture& depth = ctx.texture("depth");
    if (fb_depth_ != depth.id() || fb_normal_ != ctx.texture("normal").id() ||
        fb_position_ != ctx.texture("position").id() || fb_albedo_ != ctx.texture("albedo").id()) {
      fb_ = gl::Framebuffer();
      fb_.attach_color(0, ctx.texture("normal"));
      fb_.attach_color(1, ctx.texture("position"));
      fb_.attach_color(2, ctx.texture("albedo"));
      fb_.attach_depth(depth);
      if (Status s = fb_.finish(); !s) return s;
      fb_depth_ = depth.id();
      fb_normal_ = ctx.texture("normal").id();
      fb_position_ = ctx.texture("position").id();
      fb_albedo_ = ctx.texture("albedo").id();
    }
    fb_.bind();
    const float zero[4] = {0, 0, 0, 0};
    const float one = 1.0f;
    for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(fb_.id(), GL_COLOR, i, zero);
    glClearNamedFramebufferfv(fb_.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    const exec::FrameInputs& f = ctx.frame();
    p.program().set("u_view", f.view());
    p.program().set("u_projection", f.projection());
    if (f.scene) f.scene->draw(p.program(), 0, true);
    glDisable(GL_DEPTH_TEST);
    return {};
  }

 private:
  gl::Framebuffer fb_;
  GLuint fb_depth_ = 0, fb_normal_ = 0, fb_position_ = 0, fb_albedo_ = 0;
};

}  // namespace

exec::PassType gbuffer_pass_type() {
  return exec::PassDeclBuilder("gbuffer")
      .describe("Depth/normal/position/albedo pre-pass from the camera (raster)")
      .imported("scene")
      .imported("camera")
      .depth_out("depth")
      .color_out("normal", {Format::RGBA16F, Format::RGBA32F})
      .color_out("position", {Format::RGBA32F})
      .color_out("albedo", {Format::RGBA8, Format::RGBA16F})
      .same_size({"depth", "normal", "position", "albedo"})
      .build<GBufferPass>();
}

}  // namespace penumbra::passes
