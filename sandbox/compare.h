#pragma once
// Compare mode's state and its pieces outside the controller: which technique to compare with
// by default, setting the second session up like the first, and the mask statistics (the
// second session plays the reference).
//
//   configure_partner(*secondary, *primary, "reference", w, h);
//   update_compare_stats(state, *primary, *secondary);   // state.stats, rmse_history
#include <optional>
#include <string>
#include <vector>

#include "metrics/mask_metrics.h"
#include "technique/technique.h"
#include "technique/technique_session.h"

namespace penumbra::sandbox {

struct CompareState {
  bool enabled = false;
  std::string with;                 // secondary technique
  enum class View { split, error } view = View::split;
  float split = 0.5f;               // split position, fraction of the width (left = primary)
  // Three-way: A | B | the reference, a third session running the reference technique right of
  // `split2`; the statistics are A's (stats) and B's (stats_b) against the reference.
  bool three_way = false;
  float split2 = 0.75f;
  std::optional<metrics::MaskErrors> stats_b;
  float error_max = 0.25f;          // |a - b| shown white in the heat map
  // The error view shows the pixel classes the statistics are split by instead of the error
  // (metrics/pixel_classes.h: A's G-buffer and the reference side's mask).
  bool show_classes = false;
  metrics::PixelClasses classes;    // of the last read-back
  unsigned classes_version = 0;     // counts read-backs: the display re-uploads the picture on change
  int stats_every = 10;             // frames between RMSE read-backs
  std::optional<metrics::MaskErrors> stats;  // primary vs secondary (secondary as reference)
  std::string stats_error;
  std::vector<float> rmse_history;  // one per read-back, newest last, at most kHistory
  static constexpr size_t kHistory = 240;
};

// "reference" when registered, else the technique after `primary` (wrapping), else `primary`.
std::string default_compare_partner(const technique::TechniqueRegistry& registry, const std::string& primary);

// The second session over the first's scene, size, shadow size and debug switches, running
// `technique` (recompiles only when the technique changes).
Status configure_partner(technique::TechniqueSession& secondary, technique::TechniqueSession& primary,
                         const std::string& technique, int width, int height);

// Reads both shadow masks and the receiver coverage back and compares them (secondary as the
// reference); sets state.stats or state.stats_error and appends to the RMSE history. With a
// `reference` (three-way), A and B are each compared with it instead (stats, stats_b).
void update_compare_stats(CompareState& state, technique::TechniqueSession& primary,
                          technique::TechniqueSession& secondary, technique::TechniqueSession* reference = nullptr);

// Left edges in pixels of the split view's `columns` (2: A | B, 3: A | B | reference) over
// `width`, from state.split and state.split2 (kept in order); then `width` as the last edge.
std::vector<int> column_edges(const CompareState& state, int width, int columns);

}  // namespace penumbra::sandbox
