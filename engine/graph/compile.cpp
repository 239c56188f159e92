// compile(): the graph compiler as a pipeline of named stages, read top to bottom. Each stage
// is one function in the file of its name (compile_state.h lists them) and decides one thing.
#include "graph/compile_state.h"

namespace penumbra::graph {

namespace detail {

void CompileState::error(GraphErrorCode code, const std::string& location, std::string message) {
  GraphError e;
  e.code = code;
  e.file = graph.source_file;
  e.where = location;
  e.message = std::move(message);
  errors.push_back(std::move(e));
}

int CompileState::find_resource(std::string_view name) const {
  auto it = resource_index.find(name);
  return it == resource_index.end() ? -1 : it->second;
}

bool CompileState::holds(std::string_view condition) const {
  if (condition.empty()) return true;
  auto it = conditions.find(condition);
  return it != conditions.end() && it->second.valid && it->second.holds;
}

int CompileState::version_index(int resource, int version) {
  auto& slots = version_of[resource];
  if (static_cast<int>(slots.size()) <= version) slots.resize(version + 1, -1);
  if (slots[version] < 0) {
    slots[version] = static_cast<int>(versions.size());
    VersionState v;
    v.resource = resource;
    v.version = version;
    versions.push_back(std::move(v));
  }
  return slots[version];
}

int CompileState::existing_version(int resource, int version) const {
  const auto& slots = version_of[resource];
  return version >= 0 && version < static_cast<int>(slots.size()) ? slots[version] : -1;
}

int ping_pong_partner(const CompileState& s, const ResourceUse& use) {
  if (!use.slot->ping_pong || use.write_version < 0) return -1;
  return s.existing_version(use.resource, s.versions[use.write_version].version - 2);
}

}  // namespace detail

Checked<CompiledPlan> compile(const GraphDesc& graph, const PassTypeRegistry& registry,
                              const ParameterSet& params, const CompileSettings& settings,
                              const CompileOptions& options) {
  // Formats chosen by parameters, fixed for this compile.
  GraphErrors format_errors;
  const std::optional<GraphDesc> chosen = detail::choose_formats(graph, params, format_errors);
  if (!format_errors.empty()) return format_errors;
  detail::CompileState s(chosen ? *chosen : graph, registry, params, settings, options);
  // Names -> indices; texture sizes resolved from the settings and size parameters.
  detail::index_resources(s);
  // Every `enabled` / `when` condition parsed, type-checked and evaluated once.
  detail::evaluate_conditions(s);
  // Per pass, the bindings that apply for these parameters: chosen by `when`; every parameter binding explicit.
  detail::bind_passes(s);
  // Every declaration error at once: types, slots, formats, sizes, parameters, repeat.
  detail::validate_declarations(s);
  // `enabled` and `repeat` turn declarations into the passes that exist this compile.
  detail::expand_passes(s);
  // Bindings -> versions (graph_desc.h rule); missing producers, two writers.
  detail::resolve_versions(s);
  if (!s.errors.empty()) return s.errors;
  // Drop passes whose results reach no output or side effect.
  detail::cull_passes(s);
  // Stable topological order; a cycle is an error.
  detail::order_passes(s);
  if (!s.errors.empty()) return s.errors;
  // First/last use of every version in execution order.
  detail::compute_lifetimes(s);
  // Versions -> physical textures/buffers, reusing identical descriptors.
  detail::assign_physical_resources(s);
  // The executor's view: ordered passes with bindings, parameters, physical resources.
  detail::build_plan(s);
  // Memory barriers before each pass after incoherent (image/SSBO) writes.
  detail::plan_barriers(s);
  // Bytes each pass reads and writes, from the formats and sizes of what it binds.
  detail::count_traffic(s);
  return std::move(s.plan);
}

}  // namespace penumbra::graph
