#pragma once
// The cascaded-shadow-map options render, eval and bench share (and penumbra-sandbox takes too):
//   --cascades N        1 (one map over the scene, the default) to 4, directional lights only
//   --cascade-split L   practical split scheme's lambda: 0 linear, 1 logarithmic (default 0.9)
//   --cascade-blend B   dithered band before a cascade's margin, fraction of its half side (0.1)
//   --cascade-tint      debug view: the lit image tinted by the cascade each pixel reads
// (scene/cascades.h). The shadow map's texels are shared: 4 cascades of a 2048^2 map are 1024^2 each.
//
//   const std::vector<OptionSpec> kSpecs = with_cascade_options({...});
//   Result<scene::CascadeSettings> c = parse_cascade_options(args);
#include <vector>

#include "cli/options/args.h"
#include "scene/cascades.h"
#include "util/error.h"

namespace penumbra::cli {

std::vector<OptionSpec> with_cascade_options(std::vector<OptionSpec> specs);

// Errors name the option and its range (exit code 2).
Result<scene::CascadeSettings> parse_cascade_options(const ParsedArgs& args);

}  // namespace penumbra::cli
