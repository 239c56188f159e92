#pragma once
// How far the reference technique has got, for the sandbox's progress bar, `penumbra eval` (run
// frames until the raster reference has all its samples) and tests. The executor owns the pass
// objects and exposes none of them, so the reference passes publish their progress here: the
// state of the reference pass that executed last in this process.
//
//   while (!reference::reference_progress().complete()) session.render();
#include <cstdint>
#include <string>

namespace penumbra::reference {

struct ReferenceProgress {
  std::string method;        // "raster" or "raytraced"; empty before any reference ran
  std::int64_t done = 0;     // raster: shadow maps accumulated; raytraced: rays traced
  std::int64_t total = 0;    // raster: `samples`; raytraced: receiver pixels x `rays`
  std::uint64_t resets = 0;  // times the reset rule discarded a result (reference_frame_key.h)
  bool complete() const { return total > 0 && done >= total; }
  double fraction() const { return total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0.0; }
};

ReferenceProgress reference_progress();
// Sets method, done and total (resets is kept: it only grows, through count_reference_reset()).
void publish_reference_progress(const std::string& method, std::int64_t done, std::int64_t total);
void count_reference_reset();

}  // namespace penumbra::reference
