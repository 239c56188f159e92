#pragma once
// Whether a technique's graph would run: loaded, composed into the frame and compiled at its
// default parameters (a 1920x1080 frame, a 2048² shadow map), against the pass types of
// make_pass_library(registry), with no GL. `penumbra techniques` lists a technique whose graph
// fails here as broken, with these errors, instead of as fine.
#include <vector>

#include "technique/technique.h"
#include "util/error.h"

namespace penumbra {

// Empty when the graph compiles; else every error found (file and JSON pointer in each).
std::vector<Error> technique_graph_errors(const technique::TechniqueRegistry& registry,
                                          const technique::Technique& technique);

}  // namespace penumbra
