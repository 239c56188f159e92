#include "cli/options/cascade_option.h"

#include <string>

namespace penumbra::cli {

std::vector<OptionSpec> with_cascade_options(std::vector<OptionSpec> specs) {
  const scene::CascadeSettings defaults;
  specs.push_back({"cascades", true, false, "N",
                   "cascaded shadow maps for a directional light, 1-" + std::to_string(scene::kMaxCascades) +
                       " (default 1: one map over the scene); they share the shadow map's texels"});
  specs.push_back({"cascade-split", true, false, "L",
                   "cascade split scheme: 0 linear, 1 logarithmic (default " + std::to_string(defaults.split_lambda).substr(0, 4) + ")"});
  specs.push_back({"cascade-blend", true, false, "B",
                   "band over which a cascade dithers to the next, fraction of its half side, 0-0.5 (default " +
                       std::to_string(defaults.blend).substr(0, 3) + ")"});
  specs.push_back({"cascade-tint", false, false, "",
                   "debug view: tint the lit image by the cascade each pixel reads (red, green, blue, yellow from the nearest)"});
  return specs;
}

Result<scene::CascadeSettings> parse_cascade_options(const ParsedArgs& args) {
  scene::CascadeSettings c;
  if (auto v = args.get("cascades")) {
    Result<int> n = parse_int("cascades", *v, 1, scene::kMaxCascades);
    if (!n) return n.error();
    c.count = *n;
  }
  if (auto v = args.get("cascade-split")) {
    Result<double> l = parse_real("cascade-split", *v, 0.0, 1.0);
    if (!l) return l.error();
    c.split_lambda = static_cast<float>(*l);
  }
  if (auto v = args.get("cascade-blend")) {
    Result<double> b = parse_real("cascade-blend", *v, 0.0, 0.5);
    if (!b) return b.error();
    c.blend = static_cast<float>(*b);
  }
  c.tint = args.has("cascade-tint");
  if (Status s = scene::check_cascade_settings(c); !s) return s.error();
  return c;
}

}  // namespace penumbra::cli
