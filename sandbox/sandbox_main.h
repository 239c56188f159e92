#pragma once
// The whole penumbra-sandbox program, callable with extra techniques registered (the tests'
// host registers a tiny technique of its own this way; the real binary passes none).
#include <functional>

#include "technique/technique.h"

namespace penumbra::sandbox {

using ExtraTechniques = std::function<void(technique::TechniqueRegistry&)>;
int sandbox_main(int argc, char** argv, const ExtraTechniques& extra = {});

}  // namespace penumbra::sandbox
