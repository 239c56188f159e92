#include "passes/common/shadow_uniforms.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "exec/gpu_scene.h"
#include "scene/light_faces.h"

namespace penumbra::passes {
namespace {

// A tile of the map as shadow_common.glsl's rectangles hold it: origin (xy) and side (z) in map
// UV, `w` what the array adds.
glm::vec4 tile_rect_uv(const scene::LightFace& tile, int map_size, float w) {
  const float map = static_cast<float>(map_size);
  return glm::vec4(glm::vec2(tile.origin) / map, static_cast<float>(tile.size) / map, w);
}

scene::Bounds frame_bounds(const exec::FrameInputs& frame) {
  return frame.scene ? frame.scene->cpu().bounds : scene::Bounds{};
}

// The six faces of the frame's map.
Status set_face_uniforms(const gl::Program& p, const exec::FrameInputs& frame) {
  Result<scene::PointLightFaces> faces = scene::point_light_faces(frame.light, frame_bounds(frame), frame.shadow_size);
  if (!faces) return faces.error();
  set_light_face_uniforms(p, *faces, frame.shadow_size);
  return {};
}

// shadow_common.glsl's u_cascade_* (tile rectangles in map UV, each square's world width).
void set_cascade_uniforms(const gl::Program& p, const exec::FrameInputs& frame) {
  const scene::ShadowCascades& c = frame.cascades;
  for (int i = 0; i < c.count; ++i) {
    p.set(gl::uniform_element("u_cascade_view_proj", i).c_str(), c.tiles[i].view_proj);
    p.set(gl::uniform_element("u_cascade_rect", i).c_str(), tile_rect_uv(c.tiles[i], frame.shadow_size, c.width_world[i]));
  }
  p.set("u_cascade_margin", scene::kCascadeMarginOfHalfSide);
  p.set("u_cascade_blend", c.blend);
}

}  // namespace

void set_light_face_uniforms(const gl::Program& p, const scene::PointLightFaces& faces, int map_size) {
  for (int i = 0; i < 6; ++i) {
    p.set(gl::uniform_element("u_light_face_view_proj", i).c_str(), faces.faces[i].view_proj);
    p.set(gl::uniform_element("u_light_face_rect", i).c_str(), tile_rect_uv(faces.faces[i], map_size, 0.0f));
  }
  p.set("u_light_near", faces.near_plane);
  p.set("u_light_far", faces.far_plane);
  p.set("u_light_ortho", 0);
  p.set("u_light_frustum_width", 2.0f * faces.tan_half_fov);
  p.set("u_shadow_texel", 1.0f / static_cast<float>(faces.tile));
}

Status set_shadow_uniforms(const gl::Program& p, const exec::FrameInputs& frame, SixFaces six_faces) {
  const scene::ShadowFrustum& s = frame.shadow;
  p.set("u_light_size_world", frame.light.size);
  p.set("u_light_dir", frame.light.direction);
  p.set("u_light_pos", frame.light.position);
  const scene::Bounds bounds = frame_bounds(frame);
  p.set("u_light_emitter_distance", frame.scene ? scene::emitter_distance(frame.light, bounds) : 1.0f);
  p.set("u_blocker_height_scale", frame.scene ? scene::blocker_height_scale(frame.light, bounds) : 1.0f);
  if (s.six_faces) {
    if (six_faces == SixFaces::refused)
      return make_error(std::string("a point light inside the scene bounds needs a shadow map in every direction, "
                                    "which this pass does not read (techniques that do: ") +
                            kTiledMapTechniques + "; or move the light outside the bounds)",
                        ErrorKind::bad_input);
    return set_face_uniforms(p, frame);
  }
  p.set("u_light_view_proj", s.view_proj);
  p.set("u_light_view", s.view);
  p.set("u_light_near", s.near_plane);
  p.set("u_light_far", s.far_plane);
  p.set("u_light_ortho", s.orthographic ? 1 : 0);
  const float width = s.orthographic ? s.width_world : 2.0f * s.tan_half_fov;
  p.set("u_light_frustum_width", width);
  p.set("u_shadow_texel", 1.0f / static_cast<float>(std::max(frame.shadow_size, 1)));
  if (frame.cascades.count > 1) {
    if (six_faces == SixFaces::refused)
      return make_error(std::string("cascaded shadow maps keep each cascade in a tile of the map, which this pass "
                                    "does not read (techniques that do: ") +
                            kTiledMapTechniques + "; or use one cascade)",
                        ErrorKind::bad_input);
    set_cascade_uniforms(p, frame);
  }
  return {};
}

}  // namespace penumbra::passes
