#pragma once
// A pass type that writes texels the test chose into its `out` slot every frame, so the pass
// under test reads known input: put it before that pass in a graph (or in place of the pass
// that would have written the input) and compare what comes out.
//
//   TextureImage ramp{4, 1, 1, {0.0f, 0.25f, 0.5f, 1.0f}};           // rows top to bottom
//   library.add(test::upload_pass_type("upload_ramp", graph::Format::R32F, ramp));
//   // graph: {"type": "upload_ramp", "name": "input", "slots": {"out": "ramp"}}, then the pass
//
// Colour formats are written like a colour attachment, DEPTH32F like a depth attachment (no
// barrier is needed before a later read). The texture bound to `out` must be exactly
// texels.width x texels.height with texels.channels channels; execute() returns an Error saying
// both sizes otherwise.
#include <string>

#include "exec/pass.h"
#include "test_support/read_back.h"

namespace penumbra::test {

exec::PassType upload_pass_type(const std::string& type_name, graph::Format format, TextureImage texels);

}  // namespace penumbra::test
