#include "passes/sampling/rotation_noise.h"

namespace penumbra::passes {

graph::ParamDesc rotation_noise_param() {
  return graph::enum_param("rotation_noise", "surface", {"surface", "screen"},
                           "Per-receiver rotation of the taps: surface (IGN over half-texel cells of the shadow map, "
                           "steady under camera motion) or screen (the papers' IGN of the pixel; swims under a pan)");
}

void set_rotation_noise(const gl::Program& p, exec::PassContext& ctx) {
  p.set("u_noise_on_screen", ctx.enumeration("rotation_noise") == "screen" ? 1 : 0);
}

}  // namespace penumbra::passes
