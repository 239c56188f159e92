#pragma once
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "exec/gpu_scene.h"
#include "exec/pass.h"
#include "gl/framebuffer.h"
#include "scene/light_faces.h"

namespace penumbra::passes {

// The light-view depth map: light_view_pass_type() (light_view_pass.h) with no colour target.
exec::PassType shadow_map_pass_type();

// Clears `target`'s depth and draws the scene's casters (alpha-tested) from `view_proj` with
// the slope-scaled + constant polygon offset. `program` is the shadow_map program
// (passes/shadow_map/shadow_map.{vert,frag}.glsl); the reference renders its sample maps
// with this too, so both biases mean the same thing everywhere. Colour attachment i, if any, is
// cleared to colour_clears[i] (light_view_pass.h's state contract).
void render_depth_map(const gl::Framebuffer& target, const gl::Program& program, const exec::GpuScene& scene,
                      const glm::mat4& view_proj, float slope_bias, float constant_bias, GLuint texture_unit = 0,
                      const std::vector<glm::vec4>& colour_clears = {});

// The same for a map of several views, each drawn inside its own tile (viewport and scissor):
// a point light's six faces (scene/light_faces.h). The whole target is cleared first.
void render_depth_faces(const gl::Framebuffer& target, const gl::Program& program, const exec::GpuScene& scene,
                        std::span<const scene::LightFace> faces, float slope_bias, float constant_bias,
                        GLuint texture_unit = 0, const std::vector<glm::vec4>& colour_clears = {});

}  // namespace penumbra::passes
