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
  report.rows.push_back({"hard", e, 1.5});
  const nlohmann::json j = nlohmann::json::parse(measurement::eval_report_json(report));
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j["scene"], "ball");
  EXPECT_EQ(j["reference"], "raytraced");
  ASSERT_EQ(j["rows"].size(), 1u);
  const nlohmann::json& row = j["rows"][0];
  EXPECT_EQ(row.size(), 8u);
  EXPECT_EQ(row["technique"], "hard");
  EXPECT_DOUBLE_EQ(row["rmse"].get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(row["rmse_penumbra"].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(row["mae"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(row["max_error"].get<double>(), 0.9);
  EXPECT_DOUBLE_EQ(row["ssim"].get<double>(), 0.8);
  EXPECT_DOUBLE_EQ(row["edge_error"].get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(row["gpu_ms"].get<double>(), 1.5);
}
