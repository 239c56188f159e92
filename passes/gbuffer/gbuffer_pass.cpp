// G-buffer pre-pass: the frame's first pass (technique/frame_graph.h). A raster pass: the
// depth test's z-buffer, linear view depth, the octahedral world normal and base colour.
// Positions are rebuilt from the view depth (gbuffer_read.glsl), not stored.
#include "passes/gbuffer/gbuffer_pass.h"

#include <algorithm>
#include <iterator>

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
    gl::Texture& zbuffer = ctx.texture("zbuffer");
    const GLuint ids[4] = {zbuffer.id(), ctx.texture("depth").id(), ctx.texture("normal").id(),
                           ctx.texture("albedo").id()};
    if (!std::equal(std::begin(ids), std::end(ids), std::begin(fb_ids_))) {
      fb_ = gl::Framebuffer();
      fb_.attach_color(0, ctx.texture("depth"));
      fb_.attach_color(1, ctx.texture("normal"));
      fb_.attach_color(2, ctx.texture("albedo"));
      fb_.attach_depth(zbuffer);
      if (Status s = fb_.finish(); !s) return s;
      std::copy(std::begin(ids), std::end(ids), std::begin(fb_ids_));
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
  GLuint fb_ids_[4] = {0, 0, 0, 0};  // zbuffer, depth, normal, albedo the framebuffer holds
};

}  // namespace

exec::PassType gbuffer_pass_type() {
  return exec::PassDeclBuilder("gbuffer")
      .describe("Z-buffer, linear view depth, octahedral normal and albedo pre-pass from the camera (raster)")
      .imported("scene")
      .imported("camera")
      .depth_out("zbuffer")
      .color_out("depth", {Format::R32F})
      .color_out("normal", {Format::RG16})
      .color_out("albedo", {Format::RGBA8})
      .same_size({"zbuffer", "depth", "normal", "albedo"})
      .build<GBufferPass>();
}

}  // namespace penumbra::passes
