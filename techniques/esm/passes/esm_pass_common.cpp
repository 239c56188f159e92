#include "techniques/esm/passes/esm_pass_common.h"

#include <string>

#include "exec/gpu_scene.h"

namespace penumbra::esm {

Result<EsmViews> frame_views(const exec::PassContext& ctx, int map_size) {
  const exec::FrameInputs& f = ctx.frame();
  const scene::Bounds bounds = f.scene ? f.scene->cpu().bounds : scene::Bounds{};
  return make_esm_views(f.light, f.shadow, bounds, map_size);
}

void set_view_uniforms(const gl::Program& p, const EsmViews& v) {
  const GLuint id = p.id();
  for (size_t i = 0; i < v.faces.size(); ++i) {
    // (Appending, not "[" + to_string(i): GCC 12 warns falsely (-Wrestrict) on that form.)
    std::string matrix = "u_face_view_proj[", rect_name = "u_face_rect[";
    matrix.append(std::to_string(i)).append("]");
    rect_name.append(std::to_string(i)).append("]");
    glProgramUniformMatrix4fv(id, p.uniform_location(matrix.c_str()), 1, GL_FALSE, &v.faces[i].view_proj[0][0]);
    const glm::vec4 rect(glm::vec2(v.faces[i].origin), static_cast<float>(v.faces[i].size), 0.0f);
    glProgramUniform4fv(id, p.uniform_location(rect_name.c_str()), 1, &rect[0]);
  }
  p.set("u_face_count", static_cast<int>(v.faces.size()));
  p.set("u_esm_light", v.light);
  p.set("u_esm_ortho", v.orthographic ? 1 : 0);
  p.set("u_esm_near", v.near_plane);
  p.set("u_esm_far", v.far_plane);
  p.set("u_esm_texel_scale", v.texel_scale);
}

graph::SlotDecl blended_attachment(std::string name, graph::Format format) {
  return {std::move(name), graph::Access::read_write, graph::SlotKind::texture, {format},
          graph::Usage::color_attachment, true};
}

}  // namespace penumbra::esm
