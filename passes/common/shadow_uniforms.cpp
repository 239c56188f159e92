#include "passes/common/shadow_uniforms.h"

#include <algorithm>

#include <cmath>

#include "exec/gpu_scene.h"

namespace penumbra::passes {

void set_shadow_uniforms(const gl::Program& p, const exec::FrameInputs& frame) {
  const scene::ShadowFrustum& s = frame.shadow;
  p.set("u_light_view_proj", s.view_proj);
  p.set("u_light_view", s.view);
  p.set("u_light_near", s.near_plane);
  p.set("u_light_far", s.far_plane);
  p.set("u_light_ortho", s.orthographic ? 1 : 0);
  p.set("u_light_size_world", frame.light.size);
  float width = s.orthographic ? s.width_world : 2.0f * s.tan_half_fov;
  p.set("u_light_frustum_width", width);
  p.set("u_light_dir", frame.light.direction);
  p.set("u_light_pos", frame.light.position);
  p.set("u_shadow_texel", 1.0f / static_cast<float>(std::max(frame.shadow_size, 1)));
  p.set("u_light_emitter_distance",
        frame.scene ? scene::emitter_distance(frame.light, frame.scene->cpu().bounds) : 1.0f);
  p.set("u_blocker_height_scale", frame.scene ? scene::blocker_height_scale(frame.light, frame.scene->cpu().bounds) : 1.0f);
}

}  // namespace penumbra::passes
