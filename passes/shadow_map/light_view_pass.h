#pragma once
// A light-view raster pass: the scene's casters drawn from the light (the frame's shadow
// frustum) into a depth slot `depth` and, optionally, colour targets the technique's own
// fragment shader writes (a moment map, say). The built-in `shadow_map` is one with no colour
// target; a plugin declares its own:
//
//   library.add(passes::light_view_pass_type({
//       .type_name = "msm_moments",
//       .description = "MSM: four optimised moments of the light depth (raster)",
//       .fragment_shader = "msm/msm_moments.frag.glsl",   // #include "shadow_map/caster_material.glsl"
//       .colour_targets = {{.slot = "moments", .formats = {graph::Format::RGBA16}, .clear = {0, 0, 0, 0}}}}));
//
// GL state the pass sets (docs/writing-a-technique.md "Light-view passes"): its own framebuffer
// (`depth` as the depth attachment, colour target i at GL_COLOR_ATTACHMENT0 + i, location i in
// the shader), the viewport of the targets, depth cleared to 1 and each colour target to its
// `clear`, depth test GL_LESS with writes, polygon offset (slope_bias, constant_bias), no face
// culling (both faces cast), no blending. It leaves depth test and polygon offset disabled and
// its framebuffer bound; every raster pass binds its own.
//
// A point light inside the scene (frame.shadow.six_faces): the built-in shadow_map draws the six
// faces into tiles of its map (scene/light_faces.h), which shadow_common.glsl's readers follow;
// a pass with colour targets refuses such a light with an Error, as its readers are its own.
//
// The fragment shader sees `v_uv` and the caster's material (caster_material.glsl: call
// discard_uncovered() first), gl_FragCoord.z (the light's window depth before the polygon
// offset, the value the depth map stores less its bias) and shadow_common.glsl's uniforms
// (set_shadow_uniforms), e.g. light_distance(gl_FragCoord.z).
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "exec/pass.h"

namespace penumbra::passes {

struct LightViewTarget {
  std::string slot;
  std::vector<graph::Format> formats;  // accepted; empty = any colour format
  glm::vec4 clear{0.0f};               // where no caster is drawn
};

struct LightViewPassSpec {
  std::string type_name;
  std::string description;
  std::string fragment_shader;  // shader path (a plugin's: relative to its directory)
  std::vector<LightViewTarget> colour_targets;
  // The pass's parameters besides slope_bias and constant_bias (graph/parameters.h's makers).
  std::vector<graph::ParamDesc> params;
  // Sets the fragment shader's own uniforms each frame, before the casters are drawn.
  std::function<void(exec::PassContext&, const gl::Program&)> set_uniforms;
};

exec::PassType light_view_pass_type(LightViewPassSpec spec);

}  // namespace penumbra::passes
