#pragma once
// Sets the uniforms declared in passes/common/shadow_common.glsl from the frame's light.
#include "exec/frame_inputs.h"
#include "gl/program.h"
#include "scene/light_faces.h"
#include "util/error.h"

namespace penumbra::passes {

// Whether a pass reads a map of tiles: the six-face map of a point light inside the scene
// (scene/light_faces.h) or cascades (scene/cascades.h). Its shader places every tap with
// shadow_common.glsl's shadow_tap() / shadow_coord(), which pick the face by direction and keep
// a cascade's taps in its tile. A pass whose shader offsets shadow-map UV itself `refuses` them.
enum class SixFaces { refused, read };

// The built-in techniques that read six faces and cascades (every one; pmchss's min-filter variant
// refuses both): what a refusing plugin pass's error names.
inline constexpr const char* kTiledMapTechniques = "hard, pcf, pcss, pmchss, mpg, sspcss and esm";

// For a frame whose light needs six faces (frame.shadow.six_faces) or that has cascades, a pass
// that refuses them gets a bad-input Error naming the techniques that shadow such a light (the executor adds the
// pass's name).
[[nodiscard]] Status set_shadow_uniforms(const gl::Program& program, const exec::FrameInputs& frame,
                                         SixFaces six_faces = SixFaces::refused);

// shadow_common.glsl's six-face uniforms (u_light_face_*, near, far, texel, frustum width) for
// `faces` in a map of `map_size` texels; set_shadow_uniforms() sets them for the frame's light, a
// pass that renders its own faces (the raster reference's sample points) for those.
void set_light_face_uniforms(const gl::Program& program, const scene::PointLightFaces& faces, int map_size);

// The shadow-map window depth bias units as documented for the shadow_map pass.
struct ShadowBias {
  float slope_scale = 1.5f;  // glPolygonOffset factor: bias grows with the depth slope
  float constant = 2.0f;     // glPolygonOffset units: multiples of the smallest depth step
};

}  // namespace penumbra::passes
