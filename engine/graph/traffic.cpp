// Stage: count the bytes every pass moves, and the `--traffic` table.
//
// The model is deliberately simple, so that a person can check it by hand (docs/graph-format.md,
// "Traffic"): each bound resource counts once at its full size, as if every texel were fetched
// from memory once and every further tap of the same texel hit the cache. A filter of many taps
// over a screen texture therefore costs what one tap costs; a shadow map sampled by a screen
// pass costs its whole size, whatever part of it the receivers project to.
#include <algorithm>
#include <cstdio>
#include <string>

#include "graph/compile_state.h"

namespace penumbra::graph {

namespace {

bool reads(const PlannedBinding& b) {
  // The depth test reads the attachment it writes.
  return b.access != Access::write || b.usage == Usage::depth_attachment;
}
bool writes(const PlannedBinding& b) { return b.access != Access::read; }

double megabytes(std::uint64_t bytes) { return static_cast<double>(bytes) / 1e6; }

}  // namespace

const PlannedBinding* dispatch_tile_list(const PlannedPass& pass) {
  for (const PlannedBinding& b : pass.bindings)
    if (b.usage == Usage::indirect_dispatch) return &b;
  return nullptr;
}

PassTraffic pass_traffic(const CompiledPlan& plan, const PlannedPass& pass, double tile_fraction) {
  PassTraffic t;
  const PlannedBinding* list = dispatch_tile_list(pass);
  const bool tiled = list != nullptr && tile_fraction < 1.0;
  const double share = std::clamp(tile_fraction, 0.0, 1.0);
  for (const PlannedBinding& b : pass.bindings) {
    if (b.physical < 0 || b.usage == Usage::imported) continue;
    const PhysicalResource& r = plan.physical[b.physical];
    // Textures of the area the list's tiles cut are touched only in the tiles dispatched.
    const bool over_tiles = tiled && r.width == list->tiled_width && r.height == list->tiled_height;
    const bool scaled = over_tiles || (tiled && b.usage == Usage::indirect_dispatch);
    const std::uint64_t bytes = scaled ? static_cast<std::uint64_t>(static_cast<double>(r.bytes) * share) : r.bytes;
    if (reads(b)) t.read_bytes += bytes;
    if (writes(b)) t.written_bytes += bytes;
  }
  return t;
}

std::string traffic_table(const CompiledPlan& plan) {
  const double pixels = static_cast<double>(plan.settings.screen_w) * plan.settings.screen_h;
  std::string out;
  char line[256];
  int width = 24;
  for (const PlannedPass& p : plan.passes) width = std::max(width, static_cast<int>(std::min<size_t>(p.name.size(), 64)));
  std::snprintf(line, sizeof line, "traffic at screen %dx%d, shadow %d (MB = 10^6 bytes)\n", plan.settings.screen_w,
                plan.settings.screen_h, plan.settings.shadow_size);
  out += line;
  std::snprintf(line, sizeof line, "%-*s %-22s %10s %10s %8s\n", width, "pass", "type", "read MB", "written MB", "B/px");
  out += line;
  PassTraffic technique, frame;
  auto row = [&](const std::string& name, const std::string& type, const PassTraffic& t) {
    std::snprintf(line, sizeof line, "%-*s %-22s %10.2f %10.2f %8.2f\n", width, name.c_str(), type.c_str(),
                  megabytes(t.read_bytes), megabytes(t.written_bytes), static_cast<double>(t.total()) / pixels);
    out += line;
  };
  bool any_frame_pass = false;
  for (const PlannedPass& p : plan.passes) {
    row(p.name, p.type, p.traffic);
    PassTraffic& sum = p.frame ? frame : technique;
    any_frame_pass = any_frame_pass || p.frame;
    sum.read_bytes += p.traffic.read_bytes;
    sum.written_bytes += p.traffic.written_bytes;
  }
  if (any_frame_pass) {
    row("technique passes", "", technique);
    row("frame passes", "", frame);
  }
  row("total", "", {technique.read_bytes + frame.read_bytes, technique.written_bytes + frame.written_bytes});
  return out;
}

namespace detail {

void count_traffic(CompileState& s) {
  for (PlannedPass& p : s.plan.passes) p.traffic = pass_traffic(s.plan, p);
}

}  // namespace detail
}  // namespace penumbra::graph
