#pragma once
// Small GL pass types for executor tests: a raster fill, a compute add (sampled in, image
// out), an in-place compute scale, and a pass that only counts its executions.
#include <map>
#include <string>

#include "exec/pass.h"

namespace penumbra::test {

// Executions per pass instance name, reset by the tests.
std::map<std::string, int>& execution_counts();

void register_test_passes(exec::PassLibrary& library);

}  // namespace penumbra::test
