// The real window under Xvfb: the viewport beside the panel shows the whole frame (the same
// pixels a headless run renders), a refused frame is shown as refused and never as the previous
// image, and the scripts' `metrics` step writes the compare statistics and per-pass times.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <vector>
#include <string>

#include <nlohmann/json.hpp>

#include "image_stats.h"
#include "test_support/temp_dir.h"
#include "xvfb_run.h"

namespace {

namespace fs = std::filesystem;
using namespace penumbra::sandbox_test;

constexpr int kFrameW = 480, kFrameH = 320;
const std::string kFrame = " --size 480x320 --shadow-size 512";

// The viewport holds the frame 1:1 in the window's right-most kFrameW columns, from the top.
int viewport_x0(const Rgba& window) { return window.width - kFrameW; }

double luminance_difference(const Rgba& window, int wx0, const Rgba& frame, int fx0, int columns) {
  double sum = 0.0;
  for (int y = 0; y < kFrameH; ++y)
    for (int x = 0; x < columns; ++x) sum += std::abs(window.luminance(wx0 + x, y) - frame.luminance(fx0 + x, y));
  return sum / (double(kFrameH) * columns);
}

// Fraction of the viewport in the refused colour (DisplayPass::kRefusedColor, about 89,10,15).
double refused_fraction(const Rgba& window) {
  size_t n = 0;
  for (int y = 0; y < kFrameH; ++y)
    for (int x = viewport_x0(window); x < window.width; ++x) {
      const unsigned char* p = window.at(x, y);
      if (std::abs(p[0] - 89) < 8 && std::abs(p[1] - 10) < 8 && std::abs(p[2] - 15) < 8) ++n;
    }
  return double(n) / (double(kFrameW) * kFrameH);
}

std::string script_file(const fs::path& dir, const std::string& text) {
  const fs::path p = dir / "script.json";
  std::ofstream(p) << text;
  return p.string();
}

TEST(SandboxXvfbViewport, TheWholeFrameIsVisibleBesideThePanel) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  const fs::path dir = penumbra::test::fresh_temp_dir("sandbox_xvfb_viewport");
  const std::string common = std::string(SANDBOX_TEST_HOST) + " --scene ball --technique hard" + kFrame;
  RunResult w = run_in_xvfb(x, common + " --screenshot " + (dir / "window.png").string());
  ASSERT_EQ(w.exit_code, 0) << w.output;
  RunResult h = run(common + " --context osmesa --screenshot " + (dir / "frame.png").string());
  ASSERT_EQ(h.exit_code, 0) << h.output;
  const Rgba window = read_rgba((dir / "window.png").string()), frame = read_rgba((dir / "frame.png").string());
  ASSERT_EQ(frame.width, kFrameW);
  ASSERT_EQ(window.height, kFrameH);
  ASSERT_GT(window.width, kFrameW + 200) << "the window holds the panel beside the frame";
  // Probe strips: the frame's left edge (where the old panel covered it), middle and right edge.
  for (int fx : {0, kFrameW / 2 - 20, kFrameW - 40}) {
    const double d = luminance_difference(window, viewport_x0(window) + fx, frame, fx, 40);
    EXPECT_LT(d, 4.0) << "viewport columns " << fx << "..+40 differ from the headless frame by " << d;
  }
  // And the panel really is beside it: the window's left part is not the frame.
  EXPECT_GT(luminance_difference(window, 0, frame, 0, 40), 8.0);
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(SandboxXvfbViewport, ARefusedFrameIsShownAsRefusedNeverAsTheLastImage) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  const fs::path dir = penumbra::test::fresh_temp_dir("sandbox_xvfb_refused");
  const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
  const std::string script = script_file(
      dir, R"([{"technique": "hard"}, {"wait": 2}, {"screenshot": ")" + a + R"("},
               {"technique": "sandbox_tiny"}, {"set": {"refuse": true}}, {"wait": 2}, {"screenshot": ")" + b + R"("},
               {"set": {"refuse": false}}, {"wait": 2}, {"screenshot": ")" + c + R"("}])");
  RunResult r = run_in_xvfb(x, std::string(SANDBOX_TEST_HOST) + " --scene ball" + kFrame + " --script " + script);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("frame refused"), std::string::npos) << r.output;
  const Rgba before = read_rgba(a), refused = read_rgba(b), after = read_rgba(c);
  ASSERT_GT(refused.width, kFrameW);
  EXPECT_LT(refused_fraction(before), 0.01);
  EXPECT_GT(refused_fraction(refused), 0.8) << "the refused frame must not show the previous technique's image";
  EXPECT_GT(luminance_difference(refused, viewport_x0(refused), before, viewport_x0(before), kFrameW), 20.0);
  EXPECT_LT(refused_fraction(after), 0.01) << "a good frame replaces the refused one";
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(SandboxXvfbViewport, MetricsStepWritesCompareStatisticsAndPassTimes) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  const fs::path dir = penumbra::test::fresh_temp_dir("sandbox_xvfb_metrics");
  const std::string json_path = (dir / "m.json").string(), csv_path = (dir / "m.csv").string();
  const std::string script = script_file(
      dir, R"([{"technique": "sandbox_tiny"}, {"compare": {"with": "hard", "view": "split"}}, {"wait": 12},
               {"metrics": ")" + json_path + R"("}, {"metrics": ")" + csv_path + R"("}])");
  RunResult r = run_in_xvfb(x, std::string(SANDBOX_TEST_HOST) + " --scene ball" + kFrame + " --script " + script);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(json_path);
  ASSERT_TRUE(in) << "no " << json_path;
  const nlohmann::json m = nlohmann::json::parse(in);
  EXPECT_EQ(m["technique"]["name"], "sandbox_tiny");
  EXPECT_EQ(m["size"], nlohmann::json({kFrameW, kFrameH}));
  ASSERT_TRUE(m["passes"].is_array());
  ASSERT_FALSE(m["passes"].empty());
  bool fill = false;
  for (const auto& p : m["passes"]) {
    EXPECT_GE(p["last_ms"].get<double>(), 0.0);
    fill = fill || p["name"] == "fill";
  }
  EXPECT_TRUE(fill) << m["passes"].dump();
  const nlohmann::json& k = m["compare"];
  ASSERT_TRUE(k.is_object()) << m.dump();
  EXPECT_EQ(k["with"]["name"], "hard");
  // The tiny technique's stripes against hard shadows: a real error, measured on receivers.
  EXPECT_GT(k["pixels"].get<double>(), 1000.0);
  EXPECT_GT(k["rmse"].get<double>(), 0.01);
  EXPECT_LE(k["rmse"].get<double>(), 1.0);
  EXPECT_GE(k["max_error"].get<double>(), k["mae"].get<double>());
  // Hard shadows have no penumbra: its RMSE is n/a (null), not a perfect 0.
  EXPECT_EQ(k["penumbra_pixels"], 0);
  EXPECT_TRUE(k["rmse_penumbra"].is_null()) << k.dump();
  EXPECT_FALSE(k["rmse_history"].empty());
  EXPECT_FALSE(k["passes"].empty());
  std::ifstream csv(csv_path);
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "side,pass,type,last_ms,median_ms");
  if (!HasFailure()) fs::remove_all(dir);
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  EXPECT_TRUE(in) << "no " << p;
  return in ? nlohmann::json::parse(in) : nlohmann::json();
}

// The tiny technique's mask (darken on): lit_level 0.5 halved inside 8-pixel stripes on
// geometry (even stripe index), 1 halved elsewhere.
float tiny_mask_at(int texel_x) { return (texel_x / 8) % 2 == 0 ? 0.25f : 0.5f; }

TEST(SandboxXvfbViewport, PixelInspectorReadsTheTexelUnderAZoomedPixel) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  const fs::path dir = penumbra::test::fresh_temp_dir("sandbox_xvfb_inspect");
  auto out = [&](const char* name) { return (dir / name).string(); };
  const std::string script = script_file(
      dir, R"([{"technique": "sandbox_tiny"}, {"wait": 2},
               {"inspect": {"at": [3, 300], "out": ")" + out("final.json") + R"("}},
               {"view": {"resource": "shadow_mask", "placement": "full", "map": "heat", "zoom": 4, "center": [0.25, 0.25],
                         "auto_range": true}}, {"wait": 2},
               {"inspect": {"at": [0, 160], "out": ")" + out("a.json") + R"("}},
               {"inspect": {"at": [40, 160], "out": ")" + out("b.json") + R"("}},
               {"metrics": ")" + out("m.json") + R"("}, {"screenshot": ")" + out("zoomed.png") + R"("}])");
  RunResult r = run_in_xvfb(x, std::string(SANDBOX_TEST_HOST) + " --scene ball" + kFrame + " --script " + script);
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const nlohmann::json final_image = read_json(out("final.json"));
  EXPECT_EQ(final_image["source"], "color (A)");
  EXPECT_EQ(final_image["texel"], nlohmann::json({3, 300})) << "zoom 1: texel = pixel, both counted from the top";
  EXPECT_GE(final_image["channels"].get<int>(), 3);

  // Zoom 4 about uv (0.25, 0.25): frame pixel (px, py) shows uv 0.125 + 0.25 * (pixel centre / size).
  for (const auto& [name, px] : {std::pair<const char*, int>{"a.json", 0}, {"b.json", 40}}) {
    const nlohmann::json j = read_json(out(name));
    const int tx = static_cast<int>((0.125 + 0.25 * (px + 0.5) / kFrameW) * kFrameW);
    const int ty_gl = static_cast<int>((0.125 + 0.25 * (kFrameH - 1 - 160 + 0.5) / kFrameH) * kFrameH);
    EXPECT_EQ(j["source"], "shadow_mask") << j.dump();
    ASSERT_EQ(j["texel"], nlohmann::json({tx, kFrameH - 1 - ty_gl})) << "rows counted from the top: " << j.dump();
    EXPECT_NEAR(j["value"][0].get<double>(), tiny_mask_at(tx), 1e-3) << j.dump();
  }
  EXPECT_NE(read_json(out("a.json"))["value"][0], read_json(out("b.json"))["value"][0]) << "two stripes apart";
  // Auto range: the mask's own min and max.
  const nlohmann::json m = read_json(out("m.json"));
  EXPECT_NEAR(m["viewer"]["min"].get<double>(), 0.25, 1e-3) << m["viewer"].dump();
  EXPECT_NEAR(m["viewer"]["max"].get<double>(), 0.5, 1e-3) << m["viewer"].dump();
  if (!HasFailure()) fs::remove_all(dir);
}

// The graph view of a real technique: every pass of the plan is a node (in execution order),
// its disabled passes are listed with their condition, nodes do not overlap, edges join nodes.
TEST(SandboxXvfbViewport, GraphViewListsEveryPass) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  const fs::path dir = penumbra::test::fresh_temp_dir("sandbox_xvfb_graph");
  auto out = [&](const char* name) { return (dir / name).string(); };
  const std::string script = script_file(
      dir, R"([{"technique": "pmchss"}, {"wait": 3}, {"graph": ")" + out("g.json") + R"("},
               {"metrics": ")" + out("m.json") + R"("}, {"screenshot": ")" + out("graph.png") + R"("}])");
  RunResult r = run_in_xvfb(x, std::string(SANDBOX_TEST_HOST) + " --scene ball" + kFrame + " --script " + script);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json g = read_json(out("g.json")), m = read_json(out("m.json"));
  std::vector<std::string> plan, shown, disabled;
  for (const auto& p : m["passes"]) plan.push_back(p["name"]);
  std::set<std::string> names;
  for (const auto& p : g["passes"]) {
    names.insert(p["name"].get<std::string>());
    if (p["state"] == "runs") shown.push_back(p["name"]);
    if (p["state"] == "disabled") {
      disabled.push_back(p["name"]);
      EXPECT_NE(p["why"].get<std::string>().find("enabled is"), std::string::npos) << p.dump();
    }
  }
  ASSERT_GE(plan.size(), 3u);
  EXPECT_EQ(shown, plan) << "every pass of the plan, in execution order";
  EXPECT_FALSE(disabled.empty()) << "pmchss's default variant leaves the min-filter passes disabled";
  for (const auto& e : g["edges"]) {
    EXPECT_TRUE(names.count(e["from"].get<std::string>())) << e.dump();
    EXPECT_TRUE(names.count(e["to"].get<std::string>())) << e.dump();
  }
  EXPECT_GE(g["edges"].size(), plan.size() - 1);
  const auto& ps = g["passes"];
  for (size_t i = 0; i < ps.size(); ++i)
    for (size_t j = i + 1; j < ps.size(); ++j) {
      const double dx = std::abs(ps[i]["x"].get<double>() - ps[j]["x"].get<double>());
      const double dy = std::abs(ps[i]["y"].get<double>() - ps[j]["y"].get<double>());
      EXPECT_TRUE(dx >= 0.5 * (ps[i]["w"].get<double>() + ps[j]["w"].get<double>()) - 0.5 ||
                  dy >= 0.5 * (ps[i]["h"].get<double>() + ps[j]["h"].get<double>()) - 0.5)
          << ps[i]["name"] << " overlaps " << ps[j]["name"];
    }
  int slowest = 0;
  for (const auto& p : ps) slowest += p["slowest"].get<bool>() ? 1 : 0;
  EXPECT_LE(slowest, 1);
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
