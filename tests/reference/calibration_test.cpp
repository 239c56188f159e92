// The calibration search space and optimiser (measurement/calibration.h) on analytic objectives:
// no GL. The CLI end to end is in eval_cli_test.cpp.
#include "measurement/calibration.h"

#include <gtest/gtest.h>

#include <cmath>

namespace penumbra::measurement {
namespace {

graph::ParameterSet technique_like() {
  return graph::ParameterSet({
      graph::real_param("k", 80.0, 0.1, 10000.0, "", "log-scaled: spans five decades"),
      graph::real_param("scale", 1.2, 1.0, 2.0, "", "linear"),
      graph::int_param("taps", 16, 4, 64, "", "integer"),
      graph::real_param("depth_bias", 0.001, 0.0, 0.05, "", "a bias: not fitted by default"),
      graph::bool_param("blur", true, "not a number"),
      {.name = "divisor", .type = graph::ParamType::integer, .default_value = 4, .min = 1, .max = 8,
       .description = "structural", .structural = true},
  });
}

TEST(CalibrationSpace, DefaultsAreTheFreeFloatParametersExceptBiases) {
  auto space = free_params(technique_like(), {});
  ASSERT_TRUE(space) << space.error().to_string();
  ASSERT_EQ(space->size(), 2u);
  EXPECT_EQ((*space)[0].desc.name, "k");
  EXPECT_TRUE((*space)[0].log_scale);
  EXPECT_EQ((*space)[1].desc.name, "scale");
  EXPECT_FALSE((*space)[1].log_scale);
}

TEST(CalibrationSpace, NamedParametersMustBeFreeNumbers) {
  EXPECT_TRUE(free_params(technique_like(), {"taps", "depth_bias"}));
  auto unknown = free_params(technique_like(), {"kk"});
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("kk"), std::string::npos);
  auto structural = free_params(technique_like(), {"divisor"});
  ASSERT_FALSE(structural);
  EXPECT_NE(structural.error().message.find("structural"), std::string::npos);
  auto boolean = free_params(technique_like(), {"blur"});
  ASSERT_FALSE(boolean);
  EXPECT_NE(boolean.error().message.find("bool"), std::string::npos);
  EXPECT_FALSE(free_params(technique_like(), {"k", "k"}));
}

TEST(CalibrationSpace, UnitMappingRoundTripsAndRoundsIntegers) {
  auto space = free_params(technique_like(), {"k", "scale", "taps"});
  ASSERT_TRUE(space);
  const FreeParam& k = (*space)[0];
  EXPECT_NEAR(to_unit(k, 0.1), 0.0, 1e-12);
  EXPECT_NEAR(to_unit(k, 10000.0), 1.0, 1e-12);
  EXPECT_NEAR(to_unit(k, 10.0), 0.4, 1e-12);  // two of five decades
  for (double v : {0.37, 80.0, 2500.0}) EXPECT_NEAR(from_unit(k, to_unit(k, v)), v, v * 1e-9);
  EXPECT_NEAR(from_unit((*space)[1], 0.25), 1.25, 1e-12);
  const FreeParam& taps = (*space)[2];
  EXPECT_EQ(from_unit(taps, 0.5), 34.0);
  EXPECT_EQ(std::get<int>(param_value(taps, 34.0)), 34);
  EXPECT_EQ(from_unit(taps, -3.0), 4.0);  // clamped
}

TEST(CalibrationFit, FindsTheMinimumOfASmoothBowlInsideTheBox) {
  auto space = free_params(technique_like(), {"k", "scale"});
  ASSERT_TRUE(space);
  // Minimum at k = 5, scale = 1.6, in the parameters' own units; the fit starts at the defaults.
  auto bowl = [](const std::vector<double>& v) -> Result<double> {
    return std::pow(std::log(v[0] / 5.0), 2) + 10.0 * std::pow(v[1] - 1.6, 2);
  };
  int calls = 0;
  auto fit = fit_nelder_mead(*space, {80.0, 1.2}, bowl, {.max_evaluations = 300},
                             [&](const Evaluation& e) {
                               ++calls;
                               EXPECT_LE(e.best, e.objective);
                             });
  ASSERT_TRUE(fit) << fit.error().to_string();
  EXPECT_NEAR(fit->values[0], 5.0, 0.1);
  EXPECT_NEAR(fit->values[1], 1.6, 0.01);
  EXPECT_LT(fit->objective, 1e-3);
  EXPECT_GT(fit->start_objective, 1.0);
  EXPECT_EQ(calls, fit->evaluations);
  EXPECT_LE(fit->evaluations, 300);
}

TEST(CalibrationFit, StaysInsideTheRangeWhenTheMinimumIsOutside) {
  auto space = free_params(technique_like(), {"scale"});
  ASSERT_TRUE(space);
  auto slope = [](const std::vector<double>& v) -> Result<double> {
    EXPECT_GE(v[0], 1.0);
    EXPECT_LE(v[0], 2.0);
    return -v[0];
  };
  auto fit = fit_nelder_mead(*space, {2.0}, slope, {.max_evaluations = 50});  // starts on the bound
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->values[0], 2.0, 1e-6);
}

TEST(CalibrationFit, IntegerPointsAreEvaluatedOnce) {
  auto space = free_params(technique_like(), {"taps"});
  ASSERT_TRUE(space);
  std::vector<double> seen;
  auto objective = [&](const std::vector<double>& v) -> Result<double> {
    for (double s : seen) EXPECT_NE(s, v[0]) << "evaluated twice";
    seen.push_back(v[0]);
    return std::abs(v[0] - 40.0);
  };
  auto fit = fit_nelder_mead(*space, {16.0}, objective, {.max_evaluations = 100});
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->values[0], 40.0);
  EXPECT_EQ(static_cast<size_t>(fit->evaluations), seen.size());
}

TEST(CalibrationFit, AnObjectiveErrorStopsTheFitWithThatError) {
  auto space = free_params(technique_like(), {"scale"});
  ASSERT_TRUE(space);
  int calls = 0;
  auto failing = [&](const std::vector<double>&) -> Result<double> {
    if (++calls == 3) return make_error("render failed");
    return 1.0 * calls;
  };
  auto fit = fit_nelder_mead(*space, {1.5}, failing, {.max_evaluations = 50});
  ASSERT_FALSE(fit);
  EXPECT_EQ(fit.error().message, "render failed");
  EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace penumbra::measurement
