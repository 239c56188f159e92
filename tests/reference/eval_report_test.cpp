// The eval JSON follows the schema of docs/evaluation.md exactly.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "measurement/eval_report.h"

using namespace penumbra;

TEST(EvalReport, JsonHasTheDesignSchema) {
  measurement::EvalReport report{"ball", "raytraced", {}};
  metrics::MaskErrors e;
  e.rmse = 0.1;
  e.rmse_penumbra = 0.2;
  e.mae = 0.05;
  e.max_error = 0.9;
  e.ssim = 0.8;
  e.edge_error = 0.3;
  e.penumbra_pixels = 40;
  e.geometric_edge_pixels = 7;
  e.rmse_geometric_edge = 0.6;
  e.reliability = {.reliable = true};
  report.rows.push_back({"hard", e, 1.5});
  const nlohmann::json j = nlohmann::json::parse(measurement::eval_report_json(report));
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j["scene"], "ball");
  EXPECT_EQ(j["reference"], "raytraced");
  ASSERT_EQ(j["rows"].size(), 1u);
  const nlohmann::json& row = j["rows"][0];
  EXPECT_EQ(row.size(), 13u);
  EXPECT_EQ(row["technique"], "hard");
  EXPECT_DOUBLE_EQ(row["rmse"].get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(row["rmse_penumbra"].get<double>(), 0.2);
  EXPECT_EQ(row["penumbra_pixels"], 40);
  EXPECT_EQ(row["penumbra_reliable"], true);
  EXPECT_EQ(row["penumbra_unreliable_because"], "");
  EXPECT_DOUBLE_EQ(row["rmse_geometric_edge"].get<double>(), 0.6);
  EXPECT_EQ(row["geometric_edge_pixels"], 7);
  EXPECT_DOUBLE_EQ(row["mae"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(row["max_error"].get<double>(), 0.9);
  EXPECT_DOUBLE_EQ(row["ssim"].get<double>(), 0.8);
  EXPECT_DOUBLE_EQ(row["edge_error"].get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(row["gpu_ms"].get<double>(), 1.5);
}

// No soft penumbra (a point light, --light-size 0): the penumbra RMSE is not applicable, null in
// the JSON and "n/a" in the table, never 0; the row is marked unreliable with the reason.
TEST(EvalReport, NoSoftPenumbraIsNotApplicableNotZero) {
  measurement::EvalReport report{"ball", "raytraced", {}};
  metrics::MaskErrors e;
  e.rmse = 0.1;
  e.reliability = {.reliable = false, .reason = "no soft penumbra"};
  report.rows.push_back({"hard", e, 1.5});
  const nlohmann::json j = nlohmann::json::parse(measurement::eval_report_json(report));
  const nlohmann::json& row = j["rows"][0];
  EXPECT_TRUE(row["rmse_penumbra"].is_null());
  EXPECT_TRUE(row["rmse_geometric_edge"].is_null());
  EXPECT_EQ(row["penumbra_reliable"], false);
  EXPECT_EQ(row["penumbra_unreliable_because"], "no soft penumbra");
  const std::string table = measurement::eval_report_table(report);
  EXPECT_NE(table.find("n/a"), std::string::npos) << table;
  EXPECT_NE(table.find("unreliable on this frame: no soft penumbra"), std::string::npos) << table;
}
