#pragma once
// Sets the uniforms declared in passes/common/shadow_common.glsl from the frame's light.
#include "exec/frame_inputs.h"
#include "gl/program.h"

namespace penumbra::passes {

void set_shadow_uniforms(const gl::Program& program, const exec::FrameInputs& frame);

// The shadow-map window depth bias units as documented for the shadow_map pass.
struct ShadowBias {
  float slope_scale = 1.5f;  // glPolygonOffset factor: bias grows with the depth slope
  float constant = 2.0f;     // glPolygonOffset units: multiples of the smallest depth step
};

}  // namespace penumbra::passes
