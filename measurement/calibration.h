#pragma once
// Fitting a technique's free parameters to ground truth (`penumbra calibrate`): the search space
// and the optimiser, with no GL in them (unit-tested on analytic objectives).
//
// Each free parameter is searched on [0, 1] over its declared range: linearly, or on a log scale
// when the range spans two decades or more (k in 0.1 .. 10000: a step means the same factor
// everywhere). Integer parameters are rounded after the mapping. The optimiser is NLopt's bounded
// Nelder-Mead simplex (derivative-free: the objective, a penumbra RMSE of rendered images, has no
// gradient and small plateaus), started from the technique's current values.
//
//   auto space = free_params(session.params(), {"k", "shadow_filter_max_size"});
//   auto fit = fit_nelder_mead(*space, start, objective, {.max_evaluations = 60}, on_progress);
#include <functional>
#include <string>
#include <vector>

#include "graph/parameters.h"
#include "util/error.h"

namespace penumbra::measurement {

struct FreeParam {
  graph::ParamDesc desc;
  bool log_scale = false;
};

// The named parameters of `params` as a search space; every one must exist, be a number (float or
// int), have a range and not be structural. Empty `names`: the non-structural float parameters with
// a range, except biases (`*_bias`: fitting them to penumbrae trades acne for error; name them to
// fit them anyway).
Result<std::vector<FreeParam>> free_params(const graph::ParameterSet& params, const std::vector<std::string>& names);

double to_unit(const FreeParam& p, double value);  // [min, max] -> [0, 1]
double from_unit(const FreeParam& p, double u);    // [0, 1] -> [min, max], rounded for integers
graph::ParamValue param_value(const FreeParam& p, double value);  // int or double, as declared

// One evaluation of the objective: the parameters' values (in their own units) to a number to
// minimise, or an error that stops the fit.
using Objective = std::function<Result<double>(const std::vector<double>& values)>;

struct FitOptions {
  int max_evaluations = 60;
  double initial_step = 0.15;     // of each parameter's [0, 1]
  double tolerance = 1e-3;        // relative change of the unit-space point that ends the fit
};

struct Evaluation {
  int index = 0;                  // 1-based
  std::vector<double> values;
  double objective = 0.0;
  double best = 0.0;              // best objective so far
};

struct FitResult {
  std::vector<double> values;     // the best point found
  double objective = 0.0;         // its objective
  double start_objective = 0.0;   // the objective at the start point
  int evaluations = 0;            // distinct points evaluated
  std::string stopped_because;    // "evaluation limit", "converged", ...
};

// Minimises `objective` from `start` (values in the parameters' units, clamped into range). Each
// distinct point is evaluated once (integers make neighbouring points equal); `progress` sees
// every new evaluation.
Result<FitResult> fit_nelder_mead(const std::vector<FreeParam>& space, const std::vector<double>& start,
                                  const Objective& objective, const FitOptions& options,
                                  const std::function<void(const Evaluation&)>& progress = {});

}  // namespace penumbra::measurement
