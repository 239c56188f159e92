#pragma once
// Where the per-receiver rotation of a tap pattern comes from (GLSL: tap_rotation() in
// passes/common/receiver_plane.glsl): `rotation_noise` = surface (the default: interleaved
// gradient noise over cells of the shadow map, fixed on the surface as the camera moves) or
// screen (the papers' IGN of the pixel, Sterna 2018 section 1: new rotations at every surface
// point when the camera moves, so a still shadow swims under a pan). One declaration for every
// pass with rotated taps (pcf, both PCSS passes, pmchss's mask and shadow mask).
#include "exec/pass.h"
#include "gl/program.h"
#include "graph/parameters.h"

namespace penumbra::passes {

graph::ParamDesc rotation_noise_param();
void set_rotation_noise(const gl::Program& p, exec::PassContext& ctx);  // u_noise_on_screen

}  // namespace penumbra::passes
