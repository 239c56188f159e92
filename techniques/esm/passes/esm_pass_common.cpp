#include "techniques/esm/passes/esm_pass_common.h"

#include "exec/gpu_scene.h"

namespace penumbra::esm {

Result<EsmViews> frame_views(const exec::PassContext& ctx, int map_size) {
  const exec::FrameInputs& f = ctx.frame();
  const scene::Bounds bounds = f.scene ? f.scene->cpu().bounds : scene::Bounds{};
  return make_esm_views(f.light, f.shadow, bounds, map_size, f.cascades);
}

void set_view_uniforms(const gl::Program& p, const EsmViews& v) {
  for (int i = 0; i < static_cast<int>(v.faces.size()); ++i) {
    const EsmFace& f = v.faces[static_cast<size_t>(i)];
    p.set(gl::uniform_element("u_face_view_proj", i).c_str(), f.view_proj);
    p.set(gl::uniform_element("u_face_rect", i).c_str(),
          glm::vec4(glm::vec2(f.origin), static_cast<float>(f.size), v.texel_scale[static_cast<size_t>(i)]));
  }
  p.set("u_face_count", static_cast<int>(v.faces.size()));
  p.set("u_esm_light", v.light);
  p.set("u_esm_ortho", v.orthographic ? 1 : 0);
  p.set("u_esm_near", v.near_plane);
  p.set("u_esm_far", v.far_plane);
}

graph::SlotDecl blended_attachment(std::string name, graph::Format format) {
  return {std::move(name), graph::Access::read_write, graph::SlotKind::texture, {format},
          graph::Usage::color_attachment, true};
}

}  // namespace penumbra::esm
