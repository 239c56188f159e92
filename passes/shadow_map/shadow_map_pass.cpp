// The light-view raster passes: the light's depth map (DEPTH32F) and, for a light_view_pass_type(),
// the colour targets its fragment shader writes. Two biases fight shadow acne:
//  - slope-scaled constant bias, applied here while rendering: glPolygonOffset(slope_bias,
//    constant_bias) adds slope_bias * max|dz/dx, dz/dy| + constant_bias * r to each depth,
//    r being the smallest resolvable depth step. Steep casters get more bias, flat ones less.
//  - receiver-plane depth bias, applied where the map is read (passes/common/receiver_plane.glsl):
//    each filter tap compares against the receiver's plane extrapolated to the tap instead of
//    the centre depth, so wide PCF/PCSS kernels stay acne-free on slanted receivers.
// Depth stored is the light's window depth in [0, 1]: linear in distance for a directional
// (orthographic) light, hyperbolic for a spot light (light_distance() in shadow_common.glsl).
#include "passes/shadow_map/shadow_map_pass.h"

#include "passes/common/shadow_uniforms.h"
#include "passes/shadow_map/light_view_pass.h"

#include "exec/gpu_scene.h"
#include "exec/pass_decl_builder.h"
#include "gl/framebuffer.h"

namespace penumbra::passes {
namespace {

class LightViewPass final : public exec::PassImpl {
 public:
  explicit LightViewPass(const LightViewPassSpec& spec) : spec_(spec) {
    for (const LightViewTarget& t : spec.colour_targets) clears_.push_back(t.clear);
  }

  Status execute(exec::PassContext& ctx) override {
    const exec::FrameInputs& frame = ctx.frame();
    gl::ShaderSources sources{.vertex = "passes/shadow_map/shadow_map.vert.glsl", .fragment = spec_.fragment_shader};
    if (frame.shadow.six_faces) sources.defines.push_back({"LINEAR_FACE_DEPTH", "1"});  // shadow_map.frag.glsl
    gl::ShaderProgram& p = ctx.program(sources);
    if (!p.valid()) return *p.last_error();
    gl::Texture& depth = ctx.texture("depth");
    ids_.assign(1, depth.id());  // this frame's targets (no allocation after the first frame)
    for (const LightViewTarget& t : spec_.colour_targets) ids_.push_back(ctx.texture(t.slot).id());
    if (attached_ != ids_) {
      fb_ = gl::Framebuffer();
      fb_.attach_depth(depth);
      for (size_t i = 0; i < spec_.colour_targets.size(); ++i)
        fb_.attach_color(static_cast<int>(i), ctx.texture(spec_.colour_targets[i].slot));
      if (Status s = fb_.finish(); !s) return s;
      attached_ = ids_;
    }
    if (!ctx.frame().scene) {  // nothing casts: the map stays at the far plane, the targets clear
      depth.clear(1.0f);
      for (size_t i = 0; i < clears_.size(); ++i)
        glClearNamedFramebufferfv(fb_.id(), GL_COLOR, static_cast<GLint>(i), &clears_[i][0]);
      return {};
    }
    // A plugin's fragment shader may compute what the map's readers do (light_distance, say):
    // only the built-in depth map is read by techniques that know six faces.
    const SixFaces six_faces = spec_.colour_targets.empty() ? SixFaces::read : SixFaces::refused;
    if (Status s = set_shadow_uniforms(p.program(), frame, six_faces); !s) return s;
    if (spec_.set_uniforms) spec_.set_uniforms(ctx, p.program());
    const float slope = ctx.real("slope_bias"), constant = ctx.real("constant_bias");
    if (frame.cascades.count > 1) {  // one orthographic view per tile (scene/cascades.h)
      render_depth_faces(fb_, p.program(), *frame.scene, std::span(frame.cascades.tiles.data(), frame.cascades.count),
                         slope, constant, 0, clears_);
      return {};
    }
    if (!frame.shadow.six_faces) {
      render_depth_map(fb_, p.program(), *frame.scene, frame.shadow.view_proj, slope, constant, 0, clears_);
      return {};
    }
    Result<scene::PointLightFaces> faces = scene::point_light_faces(frame.light, frame.scene->cpu().bounds, depth.width());
    if (!faces) return faces.error();
    p.program().set("u_slope_bias", slope);  // the offset a written depth needs (shadow_map.frag.glsl)
    p.program().set("u_constant_bias", constant);
    render_depth_faces(fb_, p.program(), *frame.scene, faces->faces, slope, constant, 0, clears_);
    return {};
  }

 private:
  LightViewPassSpec spec_;
  std::vector<glm::vec4> clears_;
  gl::Framebuffer fb_;
  std::vector<GLuint> attached_, ids_;
};


}  // namespace

void render_depth_map(const gl::Framebuffer& target, const gl::Program& program, const exec::GpuScene& scene,
                      const glm::mat4& view_proj, float slope_bias, float constant_bias, GLuint texture_unit,
                      const std::vector<glm::vec4>& colour_clears) {
  const scene::LightFace whole{view_proj, glm::ivec2(0), 0};
  render_depth_faces(target, program, scene, std::span(&whole, 1), slope_bias, constant_bias, texture_unit,
                     colour_clears);
}

void render_depth_faces(const gl::Framebuffer& target, const gl::Program& program, const exec::GpuScene& scene,
                        std::span<const scene::LightFace> faces, float slope_bias, float constant_bias,
                        GLuint texture_unit, const std::vector<glm::vec4>& colour_clears) {
  target.bind();
  glDisable(GL_SCISSOR_TEST);  // clears obey the scissor
  const float one = 1.0f;
  glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &one);
  for (size_t i = 0; i < colour_clears.size(); ++i)
    glClearNamedFramebufferfv(target.id(), GL_COLOR, static_cast<GLint>(i), &colour_clears[i][0]);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(slope_bias, constant_bias);
  for (const scene::LightFace& face : faces) {
    if (face.size > 0) {  // a tile; 0: the whole target, as bound
      glEnable(GL_SCISSOR_TEST);
      glViewport(face.origin.x, face.origin.y, face.size, face.size);
      glScissor(face.origin.x, face.origin.y, face.size, face.size);
    }
    program.set("u_light_view_proj", face.view_proj);
    scene.draw(program, texture_unit, true);
  }
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_TEST);
}

exec::PassType light_view_pass_type(LightViewPassSpec spec) {
  exec::PassDeclBuilder b(spec.type_name);
  b.describe(spec.description).imported("scene").imported("light").depth_out("depth");
  for (const LightViewTarget& t : spec.colour_targets) b.color_out(t.slot, t.formats.empty() ? graph::colour_formats() : t.formats);
  std::vector<std::string> same{"depth"};
  for (const LightViewTarget& t : spec.colour_targets) same.push_back(t.slot);
  if (same.size() > 1) b.same_size(same);
  b.real("slope_bias", 1.5, 0.0, 10.0, "", "glPolygonOffset factor: depth bias per unit of depth slope")
      .real("constant_bias", 2.0, 0.0, 1000.0, "depth steps",
            "glPolygonOffset units: constant bias in smallest depth steps");
  for (const graph::ParamDesc& param : spec.params) b.param(param);
  exec::PassType type{b.decl(), nullptr};
  type.create = [spec = std::move(spec)] { return std::make_unique<LightViewPass>(spec); };
  return type;
}

exec::PassType shadow_map_pass_type() {
  return light_view_pass_type({.type_name = "shadow_map",
                               .description = "Light-view depth map with slope-scaled constant bias (raster)",
                               .fragment_shader = "passes/shadow_map/shadow_map.frag.glsl"});
}

}  // namespace penumbra::passes
