// Stable rankings (docs/evaluation.md, "Rankings across sizes"): on every built-in scene, the
// order of the built-in techniques by soft-penumbra RMSE is the same at 256x256 and at 768x768
// wherever it is an order. A pair of techniques is ordered at a size when the larger of their
// two scores is more than 1.1 times the smaller; the test fails when a pair is ordered at both
// sizes and the two orders disagree. `penumbra eval` end to end (OSMesa, raytraced reference,
// 256 rays, defaults), so what is checked is what a user's table shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_support/run_command.h"
#include "test_support/temp_dir.h"

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kTechniques = {"hard", "pcf", "pcss", "esm", "pmchss", "mpg", "sspcss"};
constexpr double kOrdered = 1.1;

using Scores = std::map<std::string, double>;  // technique -> soft-penumbra RMSE

Scores eval_scores(const std::string& scene, const std::string& size) {
  const fs::path json = penumbra::test::temp_dir("ranking_" + scene + "_" + size) / "eval.json";
  std::string techniques;
  for (const std::string& t : kTechniques) techniques += (techniques.empty() ? "" : ",") + t;
  const std::string cmd = std::string(PENUMBRA_CLI) + " eval --context osmesa --no-cache --frames 1 --scene " + scene +
                          " --size " + size + " --techniques " + techniques + " --json " + json.string();
  const penumbra::test::CommandRun run = penumbra::test::run_command(cmd);
  EXPECT_EQ(run.exit_code, 0) << cmd << "\n" << run.output;
  Scores scores;
  std::ifstream f(json);
  if (!f) return scores;
  const nlohmann::json j = nlohmann::json::parse(f);
  for (const auto& row : j["rows"]) {
    const std::string t = row["technique"];
    // An unreliable soft penumbra would make the order meaningless: every built-in scene has one.
    EXPECT_TRUE(row["penumbra_reliable"].get<bool>()) << scene << " " << size << " " << t << ": "
                                                      << row["penumbra_unreliable_because"];
    EXPECT_TRUE(row["rmse_penumbra"].is_number()) << scene << " " << size << " " << t;
    if (row["rmse_penumbra"].is_number()) scores[t] = row["rmse_penumbra"].get<double>();
  }
  return scores;
}

std::string ranking(const Scores& s) {
  std::vector<std::pair<double, std::string>> v;
  for (const auto& [t, e] : s) v.emplace_back(e, t);
  std::sort(v.begin(), v.end());
  std::string out;
  for (const auto& [e, t] : v) out += (out.empty() ? "" : " < ") + t + " " + std::to_string(e).substr(0, 6);
  return out;
}

// -1: a before b, +1: b before a, 0: not an order (within kOrdered of each other).
int order(const Scores& s, const std::string& a, const std::string& b) {
  const double ea = s.at(a), eb = s.at(b);
  if (std::max(ea, eb) <= kOrdered * std::min(ea, eb)) return 0;
  return ea < eb ? -1 : 1;
}

class RankingStability : public testing::TestWithParam<const char*> {};

TEST_P(RankingStability, OrderIsTheSameAt256And768) {
  const std::string scene = GetParam();
  const Scores small = eval_scores(scene, "256x256"), large = eval_scores(scene, "768x768");
  const size_t n = kTechniques.size();
  ASSERT_EQ(small.size(), n);
  ASSERT_EQ(large.size(), n);
  std::printf("[ ranking ] %s 256x256: %s\n[ ranking ] %s 768x768: %s\n", scene.c_str(), ranking(small).c_str(),
              scene.c_str(), ranking(large).c_str());
  int ordered_pairs = 0;
  for (auto a = small.begin(); a != small.end(); ++a)
    for (auto b = std::next(a); b != small.end(); ++b) {
      const int os = order(small, a->first, b->first), ol = order(large, a->first, b->first);
      if (os != 0 && ol != 0) {
        ++ordered_pairs;
        EXPECT_EQ(os, ol) << scene << ": " << a->first << " " << small.at(a->first) << " / " << large.at(a->first)
                          << " against " << b->first << " " << small.at(b->first) << " / " << large.at(b->first)
                          << " (256x256 / 768x768)";
      }
    }
  // The check compares something: most pairs are ordered at both sizes.
  EXPECT_GE(ordered_pairs, static_cast<int>(n * (n - 1) / 4)) << scene;
}

INSTANTIATE_TEST_SUITE_P(BuiltInScenes, RankingStability,
                         testing::Values("fence", "ball", "poles", "colonnade", "palms", "showcase"),
                         [](const testing::TestParamInfo<const char*>& i) { return std::string(i.param); });

}  // namespace
