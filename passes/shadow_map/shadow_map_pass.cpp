// The light's depth map (DEPTH32F, raster). Two biases fight shadow acne:
//  - slope-scaled constant bias, applied here while rendering: glPolygonOffset(slope_bias,
//    constant_bias) adds slope_bias * max|dz/dx, dz/dy| + constant_bias * r to each depth,
//    r being the smallest resolvable depth step. Steep casters get more bias, flat ones less.
//  - receiver-plane depth bias, applied where the map is read (passes/common/receiver_plane.glsl):
//    each filter tap compares against the receiver's plane extrapolated to the tap instead of
//    the centre depth, so wide PCF/PCSS kernels stay acne-free on slanted receivers.
// Depth stored is the light's window depth in [0, 1]: linear in distance for a directional
// (orthographic) light, hyperbolic for a spot light (light_distance() in shadow_common.glsl).
#include "passes/shadow_map/shadow_map_pass.h"

#include "exec/gpu_scene.h"
#include "exec/pass_decl_builder.h"
#include "gl/framebuffer.h"

namespace penumbra::passes {
namespace {

class ShadowMapPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.vertex = "passes/shadow_map/shadow_map.vert.glsl",
                                        .fragment = "passes/shadow_map/shadow_map.frag.glsl"});
    if (!p.valid()) return *p.last_error();
    if (!ctx.frame().shadow.unsupported.empty())
      return make_error("shadow_map: " + ctx.frame().shadow.unsupported, ErrorKind::bad_input);
    gl::Texture& depth = ctx.texture("depth");
    if (attached_ != depth.id()) {
      fb_ = gl::Framebuffer();
      fb_.attach_depth(depth);
      if (Status s = fb_.finish(); !s) return s;
      attached_ = depth.id();
    }
    if (!ctx.frame().scene) {  // nothing casts: the map stays at the far plane
      depth.clear(1.0f);
      return {};
    }
    render_depth_map(fb_, p.program(), *ctx.frame().scene, ctx.frame().shadow.view_proj, ctx.real("slope_bias"),
                     ctx.real("constant_bias"));
    return {};
  }

 private:
  gl::Framebuffer fb_;
  GLuint attached_ = 0;
};

}  // namespace

void render_depth_map(const gl::Framebuffer& target, const gl::Program& program, const exec::GpuScene& scene,
                      const glm::mat4& view_proj, float slope_bias, float constant_bias, GLuint texture_unit) {
  target.bind();
  const float one = 1.0f;
  glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &one);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(slope_bias, constant_bias);
  program.set("u_light_view_proj", view_proj);
  scene.draw(program, texture_unit, true);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_TEST);
}

exec::PassType shadow_map_pass_type() {
  return exec::PassDeclBuilder("shadow_map")
      .describe("Light-view depth map with slope-scaled constant bias (raster)")
      .imported("scene")
      .imported("light")
      .depth_out("depth")
      .real("slope_bias", 1.5, 0.0, 10.0, "", "glPolygonOffset factor: depth bias per unit of depth slope")
      .real("constant_bias", 2.0, 0.0, 1000.0, "depth steps",
            "glPolygonOffset units: constant bias in smallest depth steps")
      .build<ShadowMapPass>();
}

}  // namespace penumbra::passes
