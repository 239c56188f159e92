#pragma once
// Shorthands for the reference pass types' parameter declarations.
#include "graph/parameters.h"

namespace penumbra::reference {

inline graph::ParamDesc int_param(const char* name, int def, int lo, int hi, const char* unit,
                                  const char* description) {
  graph::ParamDesc d{.name = name, .type = graph::ParamType::integer, .default_value = def,
                     .min = double(lo), .max = double(hi)};
  d.unit = unit;
  d.description = description;
  return d;
}

inline graph::ParamDesc real_param(const char* name, double def, double lo, double hi, const char* unit,
                                   const char* description) {
  graph::ParamDesc d{.name = name, .type = graph::ParamType::real, .default_value = def, .min = lo, .max = hi};
  d.unit = unit;
  d.description = description;
  return d;
}

}  // namespace penumbra::reference
