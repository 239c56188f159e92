#pragma once
// How far a progressive pass has got: one that refines its result over many frames (an
// accumulation) or works through one long frame (a ray trace), as the reference's passes do. The
// pass reports it through its PassContext while it executes; the executor keeps the last report
// of its plan (none after a new plan), and TechniqueSession::progress() hands it to whoever shows
// it or waits for it:
//
//   ctx.report_progress({.label = "raster", .unit = "shadow maps", .done = done_, .total = samples});
//   while (!session.progress() || !session.progress()->complete()) session.render();
#include <cstdint>
#include <string>

namespace penumbra::exec {

struct PassProgress {
  std::string label;           // what is progressing, e.g. the method: "raster", "raytraced"
  std::string unit;            // what done and total count: "shadow maps", "rays"
  std::int64_t done = 0;
  std::int64_t total = 0;
  std::uint64_t restarts = 0;  // times the pass discarded its work because an input changed
  // Nothing to do is done: a ray trace of a frame with no receiver (total 0) is complete.
  bool complete() const { return done >= total; }
  double fraction() const { return total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0.0; }
};

}  // namespace penumbra::exec
