#pragma once
// Errors of parsing and compiling a graph. Each is a penumbra::Error (file, line:col or JSON
// pointer in `where`, message naming pass / slot / resource) plus a code, so tests and tools
// can tell the kinds apart without matching text.
#include <optional>
#include <utility>
#include <vector>

#include "util/error.h"

namespace penumbra::graph {

enum class GraphErrorCode {
  malformed_json,       // syntax, nesting too deep, bad UTF-8 (line:col)
  wrong_json_type,      // a field of the wrong JSON type / missing field (JSON pointer)
  unknown_pass_type,
  unknown_slot,
  missing_required_slot,
  unknown_resource,
  duplicate_name,       // two resources / passes with one name
  read_without_producer,
  cycle,
  two_writers,          // two passes produce one version
  version_out_of_range, // name@N or a write past kMaxVersion
  format_not_accepted,  // also a resource kind the slot cannot take
  size_mismatch,        // within a same-size group
  param_unknown,        // pass type has no such parameter
  param_wrong_type,
  param_out_of_range,
  param_range_mismatch,     // a $-bound graph parameter's range / options / unit exceed the pass type's
  param_not_structural,     // enabled / when / repeat / size read a parameter that does not recompile
  unknown_param_reference,  // "$x" with no technique parameter x
  repeat_out_of_range,
  bad_condition,            // `enabled` does not parse or has the wrong type
  unknown_output,
  // Parameter bindings (docs/graph-format.md "Parameters"):
  param_unreached,          // a graph parameter no pass, condition, size or repeat reads in any variant
  param_unbound,            // a pass parameter with neither binding nor default, or unbound beside a namesake
  param_bound_twice,        // an exposure and a binding (or two exposures) of one pass parameter
  param_described_twice,    // an exposing parameter states a field equal to the one it inherits
  unknown_pass,             // "exposes" names a pass the graph does not declare
  param_shadows_frame,      // a graph parameter takes the name of a frame pass's parameter
  exposure_unresolved,      // compile() given a graph whose exposures resolve_exposures() did not fill in
};

const char* graph_error_code_name(GraphErrorCode code);

struct GraphError : Error {
  GraphErrorCode code = GraphErrorCode::malformed_json;
};

using GraphErrors = std::vector<GraphError>;

// A value or every error found (validation reports all errors at once).
template <class T>
class [[nodiscard]] Checked {
 public:
  Checked(T value) : value_(std::move(value)) {}
  Checked(GraphErrors errors) : errors_(std::move(errors)) {}
  explicit operator bool() const { return value_.has_value(); }
  bool ok() const { return value_.has_value(); }
  T& value() { return *value_; }
  const T& value() const { return *value_; }
  T& operator*() { return *value_; }
  const T& operator*() const { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  const GraphErrors& errors() const { return errors_; }

 private:
  std::optional<T> value_;
  GraphErrors errors_;
};

}  // namespace penumbra::graph
