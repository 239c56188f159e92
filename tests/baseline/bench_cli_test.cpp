// `penumbra bench` reports each pass's planned traffic beside its time, with the copy and
// texture-fetch peaks it measured, and `penumbra graph --traffic` prints the same bytes.
// Runs the built CLI on OSMesa (PENUMBRA_CLI, a compile definition).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "test_support/run_command.h"
#include "test_support/temp_dir.h"

namespace penumbra::test {
namespace {

CommandRun run_cli(const std::string& args) { return run_command(std::string(PENUMBRA_CLI) + " " + args); }

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in, nullptr, false);
}

const nlohmann::json* pass_named(const nlohmann::json& row, const std::string& name) {
  for (const auto& p : row["passes"])
    if (p["name"] == name) return &p;
  return nullptr;
}

constexpr int kWidth = 64, kHeight = 32, kShadow = 256;

// A tiled technique's row carries the share of tiles its filters ran over, which is also each
// tiled pass's tile_fraction and shows in the table; untiled, neither appears.
TEST(BenchCommand, ReportsTheShareOfPenumbraTilesOfATiledTechnique) {
  const std::string json = (fresh_temp_dir("bench_tiles") / "bench.json").string();
  CommandRun r = run_cli("bench --context osmesa --no-peaks --techniques pcss:tiles=true,pcss --scenes ball "
                         "--size 128x96 --shadow-size 512 --frames 1 --warmup 0 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("penumbra tiles"), std::string::npos) << r.output;
  nlohmann::json report = read_json(json);
  ASSERT_FALSE(report.is_discarded());
  ASSERT_EQ(report["rows"].size(), 2u);
  const auto& tiled = report["rows"][0];
  ASSERT_TRUE(tiled.contains("penumbra_tile_fraction")) << tiled.dump();
  const double share = tiled["penumbra_tile_fraction"].get<double>();
  EXPECT_GT(share, 0.0);  // the ball casts a shadow
  EXPECT_LT(share, 1.0);  // and most of the ground is lit
  for (const char* name : {"blocker_search", "filter"}) {
    const nlohmann::json* p = pass_named(tiled, name);
    ASSERT_NE(p, nullptr) << tiled.dump();
    EXPECT_DOUBLE_EQ((*p)["tile_fraction"].get<double>(), share) << name;
  }
  EXPECT_FALSE(report["rows"][1].contains("penumbra_tile_fraction")) << report["rows"][1].dump();
}

TEST(BenchCommand, ReportsTrafficBandwidthAndTheMeasuredPeaks) {
  const std::string json = (fresh_temp_dir("bench_cli") / "bench.json").string();
  CommandRun r = run_cli("bench --context osmesa --techniques hard --scenes ball --size 64x32 --shadow-size 256 "
                         "--frames 2 --warmup 0 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("measured peaks: copy"), std::string::npos) << r.output;
  nlohmann::json report = read_json(json);
  ASSERT_FALSE(report.is_discarded());

  const auto& peaks = report["peaks"];
  ASSERT_TRUE(peaks["measured"].get<bool>()) << peaks.dump();
  EXPECT_EQ(peaks["copy_buffer_bytes"].get<std::uint64_t>(), 32u << 20);  // software: the small size
  EXPECT_GT(peaks["copy_gb_per_s"].get<double>(), 0.0);
  EXPECT_GT(peaks["fetch_gtexels_per_s"].get<double>(), 0.0);
  EXPECT_NEAR(peaks["fetch_gb_per_s"].get<double>(), 4.0 * peaks["fetch_gtexels_per_s"].get<double>(), 1e-9);

  ASSERT_EQ(report["rows"].size(), 1u);
  const auto& row = report["rows"][0];
  const nlohmann::json* mask = pass_named(row, "hard_mask");
  ASSERT_NE(mask, nullptr) << row.dump();
  // The frame contract's R32F view depth + RG16 normal per pixel and the DEPTH32F shadow map, once
  // each; an R8 mask.
  EXPECT_EQ((*mask)["read_bytes"].get<std::uint64_t>(), std::uint64_t{kWidth} * kHeight * 8 + kShadow * kShadow * 4);
  EXPECT_EQ((*mask)["written_bytes"].get<std::uint64_t>(), std::uint64_t{kWidth} * kHeight * 1);
  EXPECT_FALSE((*mask)["frame"].get<bool>());
  const double ms = (*mask)["ms"].get<double>();
  ASSERT_GT(ms, 0.0);
  const double bytes = (*mask)["read_bytes"].get<double>() + (*mask)["written_bytes"].get<double>();
  EXPECT_NEAR((*mask)["gb_per_s"].get<double>(), bytes / (ms * 1e-3) / 1e9, 1e-6);
  EXPECT_NEAR((*mask)["percent_of_copy_peak"].get<double>(),
              100.0 * (*mask)["gb_per_s"].get<double>() / peaks["copy_gb_per_s"].get<double>(), 1e-6);

  double technique_ms = 0.0, total_ms = 0.0;
  for (const auto& p : row["passes"]) {
    total_ms += p["ms"].get<double>();
    if (!p["frame"].get<bool>()) technique_ms += p["ms"].get<double>();
  }
  EXPECT_TRUE((*pass_named(row, "gbuffer"))["frame"].get<bool>());
  EXPECT_TRUE((*pass_named(row, "lighting"))["frame"].get<bool>());
  EXPECT_NEAR(row["technique_ms"].get<double>(), technique_ms, 1e-9);
  EXPECT_NEAR(row["total_ms"].get<double>(), total_ms, 1e-9);
  EXPECT_LT(technique_ms, total_ms);
}

TEST(BenchCommand, WithoutPeaksThePassesAreStillReported) {
  const std::string json = (fresh_temp_dir("bench_cli") / "bench.json").string();
  CommandRun r = run_cli("bench --context osmesa --techniques hard --scenes ball --size 64x32 --shadow-size 256 "
                         "--frames 1 --warmup 0 --no-peaks --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("not measured: skipped (--no-peaks)"), std::string::npos) << r.output;
  nlohmann::json report = read_json(json);
  EXPECT_FALSE(report["peaks"]["measured"].get<bool>());
  const nlohmann::json* mask = pass_named(report["rows"][0], "hard_mask");
  ASSERT_NE(mask, nullptr);
  EXPECT_GT((*mask)["read_bytes"].get<std::uint64_t>(), 0u);
  EXPECT_EQ((*mask)["percent_of_copy_peak"].get<double>(), 0.0);
}

TEST(GraphCommand, TrafficTablePrintsTheBytesOfEveryPass) {
  CommandRun r = run_cli("graph " + std::string(PENUMBRA_SOURCE_DIR) +
                         "/techniques/baseline/hard.json --traffic --screen 3840x2160 --shadow 2048");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // hard_mask at 4K: 3840*2160*8 B (view depth + normal) + 2048^2*4 B read = 83.13 MB;
  // 3840*2160*1 B (R8 mask) written = 8.29 MB; (83.13 + 8.29) MB / 8294400 px = 11.02 B/px.
  EXPECT_NE(r.output.find("hard_mask                hard_mask                   83.13       8.29    11.02"),
            std::string::npos) << r.output;
  EXPECT_NE(r.output.find("technique passes"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace penumbra::test
