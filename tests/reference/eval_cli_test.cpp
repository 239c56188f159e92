// `penumbra eval` end to end (OSMesa, 64x48, 16 rays): it writes the JSON of docs/evaluation.md, and bad
// input exits 2 with one message and no output file.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_support/temp_dir.h"

namespace {

namespace fs = std::filesystem;

struct EvalRun {
  int code = -1;
  std::string err;
};

EvalRun run_eval(const std::string& args, const std::string& env = "") {
  const fs::path dir = penumbra::test::temp_dir("eval_test");
  const fs::path err = dir / "stderr.txt";
  const std::string cmd = env + std::string(PENUMBRA_CLI) + " eval --context osmesa " + args + " >/dev/null 2>" + err.string();
  const int status = std::system(cmd.c_str());
  EvalRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream f(err);
  std::stringstream ss;
  ss << f.rdbuf();
  r.err = ss.str();
  return r;
}

fs::path out_dir() {
  return penumbra::test::fresh_temp_dir("eval_out");
}

}  // namespace

TEST(EvalCli, WritesTheJsonSchemaAndHeatMaps) {
  const fs::path d = out_dir();
  const fs::path json = d / "eval.json";
  EvalRun r = run_eval("--scene ball --techniques hard,reference --set method=raster --set samples=16 "
                   "--set map_size=256 --size 64x48 --rays 16 --frames 2 --json " + json.string() +
                   " --heatmaps " + (d / "heat").string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream f(json);
  const nlohmann::json j = nlohmann::json::parse(f);
  EXPECT_EQ(j["scene"], "ball");
  EXPECT_EQ(j["reference"], "raytraced");
  ASSERT_EQ(j["rows"].size(), 2u);
  for (const auto& row : j["rows"]) {
    for (const char* k : {"rmse", "rmse_penumbra", "penumbra_pixels", "rmse_geometric_edge", "geometric_edge_pixels",
                          "mae", "max_error", "ssim", "edge_error", "gpu_ms"}) {
      ASSERT_TRUE(row.contains(k)) << k;
      EXPECT_TRUE(row[k].is_number()) << k;
    }
    EXPECT_TRUE(row["penumbra_reliable"].is_boolean());
    EXPECT_TRUE(row["penumbra_unreliable_because"].is_string());
    EXPECT_GE(row["rmse"].get<double>(), 0.0);
    EXPECT_LE(row["ssim"].get<double>(), 1.0);
  }
  EXPECT_EQ(j["rows"][0]["technique"], "hard");
  // A hard shadow misses the whole penumbra; the raster reference does not.
  EXPECT_GT(j["rows"][0]["rmse_penumbra"].get<double>(), j["rows"][1]["rmse_penumbra"].get<double>());
  EXPECT_TRUE(fs::exists(d / "heat" / "ball_hard_error.png"));
  EXPECT_TRUE(fs::exists(d / "heat" / "ball_reference_error.png"));
  EXPECT_TRUE(fs::exists(d / "heat" / "ball_classes.png")) << "the pixel classes the columns count";
}

// --light-size 0 makes the reference the exact hard shadow (one ray per pixel): binary, so it has
// no soft penumbra (its RMSE is not applicable: null, not 0, and the row unreliable), and a coarse
// hard shadow map differs from it along the edges; the geometric-edge column still counts.
TEST(EvalCli, LightSizeZeroGivesTheExactHardReference) {
  const fs::path d = out_dir();
  const fs::path hard = d / "hard.json";
  EvalRun r = run_eval("--scene ball --techniques hard --size 64x48 --frames 1 --light-size 0 --shadow-size 64 --json " +
                       hard.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json h = nlohmann::json::parse(std::ifstream(hard));
  const nlohmann::json& row = h["rows"][0];
  EXPECT_GT(row["edge_error"].get<double>(), 0.0);  // a 64^2 map's staircase along the edges
  EXPECT_TRUE(row["rmse_penumbra"].is_null()) << row.dump();
  EXPECT_EQ(row["penumbra_pixels"], 0);
  EXPECT_EQ(row["penumbra_reliable"], false);
  EXPECT_EQ(row["penumbra_unreliable_because"], "no soft penumbra");
  EXPECT_GT(row["geometric_edge_pixels"].get<int>(), 0);
  EXPECT_TRUE(row["rmse_geometric_edge"].is_number());
  EXPECT_EQ(run_eval("--scene ball --techniques hard --light-size -1").code, 2);
}

// The reference is cached on disk by everything that decides it: a second eval of the same frame
// reads it (same numbers), another light size misses, --no-cache renders again.
TEST(EvalCli, ReferenceIsCachedByFrameAndSettings) {
  const fs::path d = out_dir();
  const std::string cache = "PENUMBRA_CACHE_DIR=" + (d / "cache").string() + " ";
  const std::string args = "--scene ball --techniques pcss --size 64x48 --rays 16 --frames 1";
  auto eval_with_cache = [&](const std::string& extra, const fs::path& json) {
    EvalRun r = run_eval(args + " " + extra + " --json " + json.string(), cache);
    EXPECT_EQ(r.code, 0) << r.err;
    return r;
  };
  EvalRun first = eval_with_cache("", d / "a.json");
  EXPECT_EQ(first.err.find("read from the cache"), std::string::npos) << first.err;
  EvalRun second = eval_with_cache("", d / "b.json");
  EXPECT_NE(second.err.find("read from the cache"), std::string::npos) << second.err;
  const nlohmann::json a = nlohmann::json::parse(std::ifstream(d / "a.json"));
  const nlohmann::json b = nlohmann::json::parse(std::ifstream(d / "b.json"));
  EXPECT_EQ(a["rows"][0]["rmse"], b["rows"][0]["rmse"]);
  EvalRun other_light = eval_with_cache("--light-size 0.2", d / "c.json");
  EXPECT_EQ(other_light.err.find("read from the cache"), std::string::npos) << other_light.err;
  EvalRun forced = eval_with_cache("--no-cache", d / "e.json");
  EXPECT_EQ(forced.err.find("read from the cache"), std::string::npos) << forced.err;
}

// A damaged cache entry (a NaN pixel, a truncated file) is never used: eval warns naming the
// file, renders the reference again, gives the numbers of a fresh run and replaces the entry.
TEST(EvalCli, ADamagedReferenceCacheIsRenderedAgainAndReplaced) {
  const fs::path d = out_dir();
  const std::string cache = "PENUMBRA_CACHE_DIR=" + (d / "cache").string() + " ";
  const std::string args = "--scene ball --techniques pcss --size 64x48 --rays 16 --frames 1";
  EvalRun fresh = run_eval(args + " --json " + (d / "fresh.json").string(), cache);
  ASSERT_EQ(fresh.code, 0) << fresh.err;
  fs::path entry;
  for (const auto& f : fs::directory_iterator(d / "cache" / "reference")) entry = f.path();
  ASSERT_FALSE(entry.empty());
  const auto whole_size = fs::file_size(entry);
  std::uint32_t key_size = 0;
  {
    std::ifstream in(entry, std::ios::binary);
    in.seekg(8);
    in.read(reinterpret_cast<char*>(&key_size), 4);
  }
  const auto first_pixel = static_cast<std::streamoff>(8 + 4 + key_size + 8);
  const std::vector<std::pair<std::string, std::function<void()>>> damages = {
      {"is not a visibility in [0, 1]",
       [&] {
         std::fstream f(entry, std::ios::binary | std::ios::in | std::ios::out);
         f.seekp(first_pixel + 4 * 10);
         const float nan = std::numeric_limits<float>::quiet_NaN();
         f.write(reinterpret_cast<const char*>(&nan), 4);
       }},
      {"truncated or damaged", [&] { fs::resize_file(entry, whole_size - 100); }},
  };
  const nlohmann::json want = nlohmann::json::parse(std::ifstream(d / "fresh.json"));
  for (const auto& [message, damage] : damages) {
    damage();
    EvalRun r = run_eval(args + " --json " + (d / "again.json").string(), cache);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find(entry.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("read from the cache"), std::string::npos) << r.err;
    const nlohmann::json got = nlohmann::json::parse(std::ifstream(d / "again.json"));
    EXPECT_EQ(got["rows"][0]["rmse"], want["rows"][0]["rmse"]);
    EXPECT_FALSE(got["rows"][0]["rmse"].is_null());
    EXPECT_EQ(fs::file_size(entry), whole_size);  // replaced by the new one
    EvalRun cached = run_eval(args + " --json " + (d / "cached.json").string(), cache);
    EXPECT_NE(cached.err.find("read from the cache"), std::string::npos) << cached.err;
  }
}

// Items of --techniques carry settings of their own; rows are labelled by them.
TEST(EvalCli, TechniquesWithTheirOwnSettingsAreRowsOfTheirOwn) {
  const fs::path d = out_dir();
  const fs::path json = d / "variants.json";
  EvalRun r = run_eval("--scene ball --size 64x48 --rays 16 --frames 1 --json " + json.string() +
                       " --techniques pcf:kernel=box:box_size=3,pcf:kernel=vogel:radius=6");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  ASSERT_EQ(j["rows"].size(), 2u);
  EXPECT_EQ(j["rows"][0]["technique"], "pcf:kernel=box:box_size=3");
  EXPECT_EQ(j["rows"][1]["technique"], "pcf:kernel=vogel:radius=6");
  EXPECT_NE(j["rows"][0]["rmse"], j["rows"][1]["rmse"]);  // the settings reached the technique
  EvalRun bad = run_eval("--scene ball --techniques pcf:box_size=99");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("pcf:box_size=99"), std::string::npos) << bad.err;
}

// --flicker: each row's temporal change over the motion, its excess over the reference's and its
// temporal error (bounded by the two changes: |a - b| <= |a| + |b| per pixel).
TEST(EvalCli, FlickerIsTheTemporalChangeAboveTheReferences) {
  const fs::path d = out_dir();
  auto flicker = [&](const std::string& step, const std::string& name) {
    const fs::path json = d / name;
    EvalRun r = run_eval("--scene ball --size 64x48 --rays 16 --frames 1 --techniques hard,pcss --flicker pan "
                         "--flicker-frames 3 --flicker-step " + step + " --json " + json.string());
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(std::ifstream(json));
  };
  const nlohmann::json moving = flicker("2", "moving.json");
  EXPECT_EQ(moving["flicker_motion"], "pan");
  EXPECT_EQ(moving["flicker_frames"], 3);
  EXPECT_EQ(moving["flicker_step_degrees"], 2.0);
  EXPECT_GT(moving["flicker_pixels"].get<size_t>(), 1000u);  // bilinear: nearly every receiver, twice
  const double reference = moving["flicker_reference"];
  EXPECT_GE(reference, 0.0);
  for (const auto& row : moving["rows"]) {
    const double change = row["temporal_change"];
    EXPECT_GT(change, 0.0) << row["technique"];  // a 2-degree pan moves 64x48 pixels over every edge
    EXPECT_NEAR(row["flicker"].get<double>(), change - reference, 1e-9);
    const double error = row["temporal_error"];
    EXPECT_GT(error, 0.0) << row["technique"];
    EXPECT_LE(error, change + reference + 1e-9) << row["technique"];
    EXPECT_GT(row["temporal_pixels"].get<size_t>(), 0u) << row["technique"];
    EXPECT_LE(row["temporal_pixels"].get<size_t>(), moving["flicker_pixels"].get<size_t>()) << row["technique"];
  }
  // Barely moving, the same surface points keep their values: no change for anyone.
  const nlohmann::json still = flicker("0.001", "still.json");
  EXPECT_LT(still["flicker_reference"].get<double>(), 0.005);
  for (const auto& row : still["rows"]) {
    EXPECT_LT(row["temporal_change"].get<double>(), 0.005) << row["technique"];
    EXPECT_LT(row["temporal_error"].get<double>(), 0.005) << row["technique"];
  }
  EXPECT_EQ(moving["flicker_match"], 0.0);
  // Matched pixels only: fewer compared, each without resampling; the same bounds hold.
  const fs::path matched_json = d / "matched.json";
  EvalRun matched = run_eval("--scene ball --size 64x48 --rays 16 --frames 1 --techniques hard --flicker pan "
                             "--flicker-frames 3 --flicker-step 2 --flicker-match 0.25 --json " + matched_json.string());
  ASSERT_EQ(matched.code, 0) << matched.err;
  const nlohmann::json m = nlohmann::json::parse(std::ifstream(matched_json));
  EXPECT_EQ(m["flicker_match"], 0.25);
  const auto& row = m["rows"][0];
  EXPECT_NEAR(row["flicker"].get<double>(), row["temporal_change"].get<double>() - m["flicker_reference"].get<double>(), 1e-9);
  EXPECT_GE(row["temporal_error"].get<double>(), 0.0);
  for (const char* bad : {"--flicker wiggle", "--flicker-frames 4", "--flicker pan --flicker-frames 1",
                          "--flicker-match 0.1", "--flicker pan --flicker-match 0.7", "--flicker pan --flicker-match 0",
                          "--flicker pan --flicker-match 0.0005", "--flicker light --flicker-step 1px",
                          "--flicker pan --flicker-step 0px", "--flicker pan --flicker-step px",
                          "--flicker pan --flicker-step 99px", "--flicker pan --flicker-step 1pix"}) {
    EvalRun r = run_eval(std::string("--scene ball --techniques hard ") + bad);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("flicker"), std::string::npos) << r.err;
  }
}

// --flicker-step 1px: the camera turns so that the image centre moves by one pixel a frame, and a
// band around it lands on pixel centres for --flicker-match; a pan that lands none is refused
// rather than reported as a perfectly steady mask.
TEST(EvalCli, APanByWholePixelsComparesABandOfPixelsAndNoneIsAnError) {
  const fs::path d = out_dir();
  const fs::path json = d / "px.json";
  EvalRun r = run_eval("--scene avenue --size 160x90 --rays 16 --frames 1 --techniques hard --flicker pan "
                       "--flicker-frames 3 --flicker-step 1px --flicker-match 0.01 --json " + json.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  const double degrees = j["flicker_step_degrees"];
  EXPECT_GT(degrees, 0.2);  // one pixel of a 90-pixel-high view (avenue: 0.74 degrees)
  EXPECT_LT(degrees, 1.0);
  EXPECT_GT(j["flicker_pixels"].get<size_t>(), 100u);
  EXPECT_GT(j["rows"][0]["temporal_pixels"].get<size_t>(), 100u);
  const fs::path none = d / "none.json";
  EvalRun empty = run_eval("--scene avenue --size 160x90 --rays 16 --frames 1 --techniques hard --flicker pan "
                           "--flicker-frames 2 --flicker-step 0.6 --flicker-match 0.001 --json " + none.string());
  EXPECT_EQ(empty.code, 2) << empty.err;
  EXPECT_NE(empty.err.find("--flicker-step 1px"), std::string::npos) << empty.err;
  EXPECT_FALSE(fs::exists(none));
}

TEST(EvalCli, BadInputExitsTwoWithoutFiles) {
  const fs::path d = out_dir();
  const fs::path json = d / "eval.json";
  const std::string out = " --json " + json.string() + " --heatmaps " + (d / "heat").string();
  const struct {
    std::string args, says;
  } cases[] = {
      {"--scene ball --techniques nope" + out, "unknown technique 'nope'"},
      {"--scene nowhere --techniques hard" + out, "nowhere"},
      {"--scene ball --techniques hard --size 0x10" + out, "size"},
      {"--scene ball --techniques hard --reference magic" + out, "--reference"},
      {"--scene ball --techniques hard --set no_such_key=1" + out, "no_such_key"},
      {"--scene ball" + out, "--techniques"},
  };
  for (const auto& c : cases) {
    EvalRun r = run_eval(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(json)) << c.args;
    EXPECT_FALSE(fs::exists(d / "heat")) << c.args;
  }
}
