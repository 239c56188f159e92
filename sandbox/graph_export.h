#pragma once
// The graph view's model of the controller's current plan (with the last pass times), and the
// scripts' `graph` step writing it with its dot layout as JSON.
#include <string>

#include "sandbox/controller.h"
#include "sandbox/graph_view_model.h"

namespace penumbra::sandbox {

GraphViewModel current_graph_view(SandboxController& c);
Status write_graph_view(SandboxController& c, const std::string& path);

}  // namespace penumbra::sandbox
