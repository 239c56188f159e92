#include "measurement/calibration.h"

#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

namespace penumbra::measurement {

namespace {

// A range spanning this factor or more is searched on a log scale.
constexpr double kLogScaleSpan = 100.0;

struct FitState {
  const std::vector<FreeParam>* space = nullptr;
  const Objective* objective = nullptr;
  const std::function<void(const Evaluation&)>* progress = nullptr;
  std::map<std::vector<double>, double> seen;  // values -> objective
  std::optional<Error> error;
  FitResult best;
  nlopt_opt opt = nullptr;
};

double evaluate(unsigned n, const double* unit, double* /*gradient*/, void* data) {
  auto& state = *static_cast<FitState*>(data);
  std::vector<double> values(n);
  for (unsigned i = 0; i < n; ++i) values[i] = from_unit((*state.space)[i], std::clamp(unit[i], 0.0, 1.0));
  if (auto it = state.seen.find(values); it != state.seen.end()) return it->second;
  Result<double> f = (*state.objective)(values);
  if (!f) {
    state.error = f.error();
    nlopt_force_stop(state.opt);
    return HUGE_VAL;
  }
  const double value = std::isfinite(*f) ? *f : HUGE_VAL;
  state.seen.emplace(values, value);
  if (state.seen.size() == 1) state.best.start_objective = value;
  if (state.seen.size() == 1 || value < state.best.objective) {
    state.best.values = values;
    state.best.objective = value;
  }
  state.best.evaluations = static_cast<int>(state.seen.size());
  if (*state.progress) (*state.progress)({state.best.evaluations, values, value, state.best.objective});
  return value;
}

std::string stop_reason(nlopt_result r) {
  switch (r) {
    case NLOPT_MAXEVAL_REACHED: return "evaluation limit";
    case NLOPT_XTOL_REACHED: case NLOPT_FTOL_REACHED: case NLOPT_SUCCESS: return "converged";
    case NLOPT_STOPVAL_REACHED: return "target reached";
    default: return nlopt_result_to_string(r);
  }
}

}  // namespace

Result<std::vector<FreeParam>> free_params(const graph::ParameterSet& params, const std::vector<std::string>& names) {
  std::vector<FreeParam> space;
  if (names.empty()) {
    for (const graph::ParamDesc& d : params.descs())
      if (d.type == graph::ParamType::real && !d.structural && d.has_range() && !d.name.ends_with("_bias"))
        space.push_back({d, d.min > 0.0 && d.max / d.min >= kLogScaleSpan});
    if (space.empty()) return make_error("the technique has no free float parameters; name some with --params");
    return space;
  }
  for (const std::string& name : names) {
    const graph::ParamDesc* d = params.find(name);
    if (!d) {
      std::string known;
      for (const graph::ParamDesc& p : params.descs()) known += (known.empty() ? "" : ", ") + p.name;
      return make_error("unknown parameter '" + shortened(name) + "' (parameters: " + known + ")");
    }
    if (d->structural)
      return make_error("parameter '" + name + "' is structural (it changes the graph): set it with :" + name +
                        "=VALUE and fit the others");
    if (d->type != graph::ParamType::real && d->type != graph::ParamType::integer)
      return make_error("parameter '" + name + "' is " + param_type_name(d->type) +
                        ": only float and int parameters can be fitted (set the others with :k=v)");
    if (!d->has_range()) return make_error("parameter '" + name + "' has no range to search");
    if (std::any_of(space.begin(), space.end(), [&](const FreeParam& p) { return p.desc.name == name; }))
      return make_error("parameter '" + shortened(name) + "' is listed twice");
    space.push_back({*d, d->min > 0.0 && d->max / d->min >= kLogScaleSpan});
  }
  return space;
}

double to_unit(const FreeParam& p, double value) {
  const double v = std::clamp(value, p.desc.min, p.desc.max);
  if (p.desc.max <= p.desc.min) return 0.0;
  if (p.log_scale) return std::log(v / p.desc.min) / std::log(p.desc.max / p.desc.min);
  return (v - p.desc.min) / (p.desc.max - p.desc.min);
}

double from_unit(const FreeParam& p, double u) {
  u = std::clamp(u, 0.0, 1.0);
  double v = p.log_scale ? p.desc.min * std::pow(p.desc.max / p.desc.min, u)
                         : p.desc.min + u * (p.desc.max - p.desc.min);
  if (p.desc.type == graph::ParamType::integer) v = std::round(v);
  return std::clamp(v, p.desc.min, p.desc.max);
}

graph::ParamValue param_value(const FreeParam& p, double value) {
  if (p.desc.type == graph::ParamType::integer) return static_cast<int>(std::lround(value));
  return value;
}

Result<FitResult> fit_nelder_mead(const std::vector<FreeParam>& space, const std::vector<double>& start,
                                  const Objective& objective, const FitOptions& options,
                                  const std::function<void(const Evaluation&)>& progress) {
  if (space.empty() || start.size() != space.size())
    return make_error("calibration needs one start value per free parameter", ErrorKind::internal);
  const unsigned n = static_cast<unsigned>(space.size());
  std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(nlopt_create(NLOPT_LN_NELDERMEAD, n), nlopt_destroy);
  if (!opt) return make_error("cannot create the Nelder-Mead optimiser", ErrorKind::internal);
  std::vector<double> lower(n, 0.0), upper(n, 1.0), step(n), x(n);
  for (unsigned i = 0; i < n; ++i) {
    x[i] = to_unit(space[i], start[i]);
    // Step inwards from a start on the boundary, so the first simplex is inside the box.
    step[i] = x[i] + options.initial_step > 1.0 ? -options.initial_step : options.initial_step;
  }
  FitState state;
  state.space = &space;
  state.objective = &objective;
  state.progress = &progress;
  state.opt = opt.get();
  nlopt_set_lower_bounds(opt.get(), lower.data());
  nlopt_set_upper_bounds(opt.get(), upper.data());
  nlopt_set_min_objective(opt.get(), evaluate, &state);
  nlopt_set_maxeval(opt.get(), std::max(1, options.max_evaluations));
  nlopt_set_xtol_rel(opt.get(), options.tolerance);
  nlopt_set_initial_step(opt.get(), step.data());
  double minimum = 0.0;
  const nlopt_result r = nlopt_optimize(opt.get(), x.data(), &minimum);
  if (state.error) return *state.error;
  if (state.seen.empty()) return make_error(std::string("the optimiser stopped before evaluating: ") +
                                            nlopt_result_to_string(r), ErrorKind::internal);
  state.best.stopped_because = stop_reason(r);
  return state.best;
}

}  // namespace penumbra::measurement
