#include "techniques/pmchss/passes/pmchss_pass_common.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "passes/common/shadow_uniforms.h"

namespace penumbra::pmchss {

using graph::ParamDesc;
using graph::ParamType;

// Defaults from Sterna 2018 and its demo (the technique's own defaults are tuned against the
// reference and stated in pmchss.json): 0.002 UV max kernel radius, 1.2 search scale (section
// 2.2), k = 80 (Listing 4).
ParamDesc shadow_filter_max_size_param() {
  return real_param("shadow_filter_max_size", 0.002, 1e-4, 0.05, "shadow-map UV",
                    "Largest PCF kernel radius, shadowFilterMaxSize (the paper: 0.002 UV = 4.1 texels at 2048^2; "
                    "physical: a cap on the light's own penumbra)");
}

ParamDesc penumbra_kernel_scale_param() {
  return real_param("penumbra_kernel_scale", 1.2, 1.0, 2.0, "",
                    "Blocker search radius / shadow_filter_max_size (section 2.2: 1.2; artifacts gone in about [1.2, 1.6])");
}

std::vector<ParamDesc> penumbra_params() {
  return {shadow_filter_max_size_param(), penumbra_kernel_scale_param(),
          enum_param("penumbra_mapping", "paper", {"paper", "physical", "fixed"},
                     "Blocker depth to kernel: paper saturate(k p^2) (Listing 4); physical PCSS width (Listing 5); "
                     "fixed 1 (Table 1 row 1)"),
          real_param("k", 80.0, 0.1, 10000.0, "", "Scale of p^2 in the paper mapping (Listing 4: 80)"),
          real_param("depth_bias", 0.0005, 0.0, 0.05, "window depth",
                     "Subtracted from the receiver depth before each comparison"),
          bool_param("receiver_plane_bias", true,
                     "Extrapolate the receiver depth along its plane to each tap (not in the paper; removes acne of "
                     "wide kernels)")};
}

Status set_pmchss_uniforms(const gl::Program& p, exec::PassContext& ctx) {
  if (Status s = passes::set_shadow_uniforms(p, ctx.frame(), passes::SixFaces::read); !s) return s;
  float max_size = ctx.real("shadow_filter_max_size");
  p.set("u_shadow_filter_max_size", max_size);
  p.set("u_search_radius", max_size * ctx.real("penumbra_kernel_scale"));
  p.set("u_penumbra_k", ctx.real("k"));
  p.set("u_depth_bias", ctx.real("depth_bias"));
  p.set("u_receiver_plane", ctx.boolean("receiver_plane_bias") ? 1 : 0);
  return {};
}

std::pair<std::string, std::string> mapping_define(exec::PassContext& ctx) {
  std::string m = ctx.enumeration("penumbra_mapping");
  return {"PENUMBRA_MAPPING", m == "physical" ? "1" : m == "fixed" ? "2" : "0"};
}

Status check_search_covers_texel(exec::PassContext& ctx, int shadow_size) {
  double radius_uv = double(ctx.real("shadow_filter_max_size")) * ctx.real("penumbra_kernel_scale");
  double texels = radius_uv * shadow_size;
  if (texels >= 1.0) return {};
  std::ostringstream m;
  m << "shadow map " << shadow_size << "x" << shadow_size
    << " texels is too small for the pmchss blocker search: its radius, penumbra_kernel_scale ("
    << ctx.real("penumbra_kernel_scale") << ") x shadow_filter_max_size ("
    << ctx.real("shadow_filter_max_size") << " shadow-map UV), covers " << texels
    << " texels, at least 1 is needed; use a shadow map of at least "
    << static_cast<int>(std::ceil(1.0 / radius_uv)) << " texels or raise shadow_filter_max_size";
  return make_error(m.str(), ErrorKind::bad_input);
}

}  // namespace penumbra::pmchss
