#include "measurement/progressive_render.h"

#include <cstdio>

namespace penumbra::measurement {

Status render_until_complete(technique::TechniqueSession& session, int max_frames,
                             const std::function<void(const exec::PassProgress&)>& on_tenth) {
  int last_tenth = -1;
  for (int frame = 0; frame < max_frames; ++frame) {
    if (Status s = session.render(); !s) return s;
    const std::optional<exec::PassProgress>& p = session.progress();
    if (!p || p->complete()) return {};
    if (const int tenth = static_cast<int>(p->fraction() * 10.0); tenth != last_tenth) {
      if (on_tenth) on_tenth(*p);
      last_tenth = tenth;
    }
  }
  return make_error("technique '" + session.technique() + "' did not complete in " + std::to_string(max_frames) +
                        " frames",
                    ErrorKind::internal);
}

std::string progress_text(const exec::PassProgress& p) {
  char buf[160];
  if (p.complete())
    std::snprintf(buf, sizeof buf, "%s: complete, %lld %s", p.label.c_str(), static_cast<long long>(p.total),
                  p.unit.c_str());
  else
    std::snprintf(buf, sizeof buf, "%s: %lld / %lld %s (%.0f%%)", p.label.c_str(), static_cast<long long>(p.done),
                  static_cast<long long>(p.total), p.unit.c_str(), 100.0 * p.fraction());
  return buf;
}

}  // namespace penumbra::measurement
