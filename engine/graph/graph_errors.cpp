#include "graph/graph_errors.h"

namespace penumbra::graph {

const char* graph_error_code_name(GraphErrorCode code) {
  switch (code) {
    case GraphErrorCode::malformed_json: return "malformed_json";
    case GraphErrorCode::wrong_json_type: return "wrong_json_type";
    case GraphErrorCode::unknown_pass_type: return "unknown_pass_type";
    case GraphErrorCode::unknown_slot: return "unknown_slot";
    case GraphErrorCode::missing_required_slot: return "missing_required_slot";
    case GraphErrorCode::unknown_resource: return "unknown_resource";
    case GraphErrorCode::duplicate_name: return "duplicate_name";
    case GraphErrorCode::read_without_producer: return "read_without_producer";
    case GraphErrorCode::cycle: return "cycle";
    case GraphErrorCode::two_writers: return "two_writers";
    case GraphErrorCode::version_out_of_range: return "version_out_of_range";
    case GraphErrorCode::format_not_accepted: return "format_not_accepted";
    case GraphErrorCode::size_mismatch: return "size_mismatch";
    case GraphErrorCode::param_unknown: return "param_unknown";
    case GraphErrorCode::param_wrong_type: return "param_wrong_type";
    case GraphErrorCode::param_out_of_range: return "param_out_of_range";
    case GraphErrorCode::param_range_mismatch: return "param_range_mismatch";
    case GraphErrorCode::param_not_structural: return "param_not_structural";
    case GraphErrorCode::unknown_param_reference: return "unknown_param_reference";
    case GraphErrorCode::repeat_out_of_range: return "repeat_out_of_range";
    case GraphErrorCode::bad_condition: return "bad_condition";
    case GraphErrorCode::unknown_output: return "unknown_output";
    case GraphErrorCode::param_unreached: return "param_unreached";
    case GraphErrorCode::param_unbound: return "param_unbound";
    case GraphErrorCode::param_bound_twice: return "param_bound_twice";
    case GraphErrorCode::param_described_twice: return "param_described_twice";
    case GraphErrorCode::unknown_pass: return "unknown_pass";
    case GraphErrorCode::param_shadows_frame: return "param_shadows_frame";
    case GraphErrorCode::exposure_unresolved: return "exposure_unresolved";
  }
  return "?";
}

}  // namespace penumbra::graph
