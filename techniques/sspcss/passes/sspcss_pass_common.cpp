#include "techniques/sspcss/passes/sspcss_pass_common.h"

#include <algorithm>
#include <cmath>

#include "passes/common/shadow_uniforms.h"

namespace penumbra::sspcss {

using graph::ParamDesc;

// The papers' values where they give one; sspcss.json states the defaults tuned against the
// reference (docs/graph-format.md "Parameters": the pass types hold the one description).
std::vector<ParamDesc> range_params() {
  return {graph::real_param("depth_sigma", 0.02, 0.001, 1.0, "fraction of view depth",
                            "Sigma of the range term: camera-space depth difference of a tap from the centre pixel's "
                            "tangent plane, relative to the centre's view depth"),
          graph::bool_param("range_term", true,
                            "Edge-aware (cross-bilateral) weighting; false = plain Gaussian / Poisson domain filter that "
                            "bleeds across depth edges (for comparison)")};
}

ParamDesc footprint_param() {
  return graph::bool_param("receiver_footprint", true,
                           "Shape the kernels as the penumbra's footprint on the receiver seen from the camera (stretched "
                           "along the light on a slanted receiver, foreshortened by the view); false = the paper's round "
                           "kernel of diameter W_screen");
}

std::vector<ParamDesc> search_params() {
  return {graph::real_param("light_size_scale", 1.0, 0.0, 10.0, "",
                            "Multiplier on the light's emitter diameter (the scene light's size, W_light)"),
          graph::real_param("max_penumbra_px", 64.0, 1.0, 256.0, "pixels",
                            "Largest screen extent of the filter kernel (W_screen, stretched by the receiver footprint) "
                            "and of the blocker-search kernel")};
}

ParamDesc fixed_radius_param() {
  return graph::real_param("fixed_radius_px", 0.0, 0.0, 128.0, "pixels",
                           "Benchmark/debug: when > 0, every receiver's W_screen is 2 x this radius, found blocker or not "
                           "(the blocker search still runs; with receiver_footprint off the kernel is exactly that disk); "
                           "0 = off");
}

ParamDesc separable_taps_param() {
  return graph::int_param("separable_taps", 16, 3, 64, "",
                          "Taps of each separable pass, whatever the kernel radius: every pixel of the kernel while it "
                          "fits, else one jittered tap per equal stratum (cost independent of the radius)");
}

ParamDesc poisson_taps_param() {
  return graph::int_param("poisson_taps", 32, 4, 64, "",
                          "Taps of the 2D Poisson disk (a fixed best-candidate set rotated per pixel)");
}

void set_screen_uniforms(const gl::Program& p, const exec::FrameInputs& frame) {
  const float tan_y = std::tan(0.5f * frame.camera.fov_y);
  p.set("u_view", frame.view());
  p.set("u_tan_half_fov", glm::vec2(tan_y * frame.aspect(), tan_y));
  p.set("u_screen_px", glm::vec2(static_cast<float>(frame.screen_w), static_cast<float>(frame.screen_h)));
  p.set("u_d_screen", 0.5f / tan_y);
}

void set_footprint_uniform(const gl::Program& p, exec::PassContext& ctx) {
  p.set("u_footprint", ctx.boolean("receiver_footprint") ? 1 : 0);
}

void set_range_uniforms(const gl::Program& p, exec::PassContext& ctx) {
  p.set("u_depth_sigma", ctx.real("depth_sigma"));
  p.set("u_range_term", ctx.boolean("range_term") ? 1 : 0);
}

Status set_penumbra_uniforms(const gl::Program& p, exec::PassContext& ctx) {
  if (Status s = passes::set_shadow_uniforms(p, ctx.frame(), passes::SixFaces::read); !s) return s;
  p.set("u_light_size_scale", ctx.real("light_size_scale"));
  p.set("u_max_penumbra_px", ctx.real("max_penumbra_px"));
  return {};
}

void set_fixed_radius_uniform(const gl::Program& p, exec::PassContext& ctx) {
  p.set("u_fixed_radius_px", ctx.real("fixed_radius_px"));
}

void set_separable_uniforms(const gl::Program& p, exec::PassContext& ctx) {
  p.set("u_taps", ctx.integer("separable_taps"));
}

void set_poisson_uniforms(const gl::Program& p, exec::PassContext& ctx, std::vector<glm::vec2>& disk) {
  // kMaxPoissonTaps in poisson_taps.glsl; the declared range of poisson_taps keeps within it.
  constexpr int kMaxTaps = 64;
  const int taps = std::clamp(ctx.integer("poisson_taps"), 1, kMaxTaps);
  if (static_cast<int>(disk.size()) != taps) disk = passes::poisson_disk(taps, kPoissonDisk);
  glProgramUniform2fv(p.id(), p.uniform_location("u_poisson"), taps, &disk[0].x);
  p.set("u_poisson_taps", taps);
}

}  // namespace penumbra::sspcss
