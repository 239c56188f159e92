#include "sandbox/graph_export.h"

#include "util/file_write.h"

namespace penumbra::sandbox {

GraphViewModel current_graph_view(SandboxController& c) {
  technique::TechniqueSession& s = c.session();
  std::vector<double> ms;
  for (const exec::PassTiming& t : s.executor().timings()) ms.push_back(t.last_ms);
  return build_graph_view(s.plan(), s.graph(), ms);
}

Status write_graph_view(SandboxController& c, const std::string& path) {
  const GraphViewModel m = current_graph_view(c);
  Result<GraphLayout> l = layout_with_dot(m.input);
  if (!l) return l.error();
  return write_file_whole(path, graph_view_json(m, &*l));
}

}  // namespace penumbra::sandbox
