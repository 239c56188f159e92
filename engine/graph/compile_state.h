#pragma once
// Internal to the compiler (not installed): the state the stages of compile() pass along.
// Names become indices once (index_resources) so the later stages touch few strings.
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "graph/compiler.h"
#include "graph/condition.h"

namespace penumbra::graph::detail {

// A condition text of the graph (`enabled`, `when`), parsed and checked once per compile.
struct ConditionState {
  bool valid = false;   // parsed and type-checked
  bool holds = false;   // its value for this compile's parameters (when valid)
  GraphErrorCode code = GraphErrorCode::bad_condition;
  std::string problem;  // when !valid
  std::vector<std::string> references;  // the parameters it reads (when parsed)
};

// A declared pass with the bindings that apply for this compile's parameter values
// (graph_desc.h's binding rule): one slot binding per bound slot, one entry per parameter of
// the pass type.
struct BoundParam {
  const ParamDesc* desc = nullptr;        // the pass type's declaration
  const ParamBinding* binding = nullptr;  // the applying binding; null: exposed or default
  const ParamExposure* exposure = nullptr; // the graph parameter exposing it, when no binding applies
  const ParamDesc* graph_param = nullptr; // the graph parameter it reads ($ or exposed); null: constant
};

// A slot binding with its names looked up once (validation and versioning both need them).
struct BoundSlot {
  const SlotBinding* binding = nullptr;
  const SlotDecl* slot = nullptr;  // null: the type has no such slot
  int resource = -1;               // -1: unbound ("") or no such resource
  bool applies = false;            // the first binding of its slot whose `when` holds
};

struct BoundPass {
  const PassDecl* decl = nullptr;
  const PassTypeDecl* type = nullptr;  // null: unknown type (reported by validate)
  std::vector<BoundSlot> declared;     // every slot binding of the declaration, in its order
  std::vector<BoundSlot> slots;        // the applying bound ones, in the pass type's slot order
  std::vector<BoundParam> params;
};

struct ResourceUse {
  const SlotDecl* slot = nullptr;
  const SlotBinding* binding = nullptr;
  int resource = -1;
  int read_version = -1;   // version index into CompileState::versions
  int write_version = -1;
};

struct ExpandedPass {
  const BoundPass* bound = nullptr;
  std::string name;
  int iteration = 0;
  std::vector<ResourceUse> uses;
  bool root = false;    // side effect: a culling root
  bool culled = false;
  int order = -1;       // position in the execution order
};

struct VersionState {
  int resource = -1;
  int version = 0;
  int producer = -1;          // expanded pass index; -1 = from outside the frame (v0)
  std::vector<int> readers;   // expanded pass indices
  bool output = false;        // graph output or kept alive: lives to the end of the frame
  int refcount = 0;           // culling
  int group = -1;             // versions that must share one physical resource
  int first_use = 0, last_use = 0;
};

// Versions that must live in one physical resource (in-place read_write chains, all
// versions of a persistent resource).
struct VersionGroup {
  int resource = -1;
  int first_use = 0, last_use = 0;
  int physical = -1;
  std::vector<int> versions;
};

struct CompileState {
  CompileState(const GraphDesc& g, const PassTypeRegistry& r, const ParameterSet& p,
               const CompileSettings& s, const CompileOptions& o)
      : graph(g), registry(r), params(p), settings(s), options(o) {}

  const GraphDesc& graph;
  const PassTypeRegistry& registry;
  const ParameterSet& params;
  CompileSettings settings;
  CompileOptions options;
  GraphErrors errors;

  std::unordered_map<std::string_view, int> resource_index;
  std::vector<int> width, height;  // resolved texture sizes per resource
  std::vector<std::uint64_t> bytes;  // resolved buffer sizes per resource (a tile list's from its grid)
  std::vector<int> tiled_width, tiled_height;  // a tile list: the area its tiles cut, pixels
  std::unordered_map<std::string_view, ConditionState> conditions;  // by condition text
  std::vector<BoundPass> bound;    // one per declared pass, declaration order
  std::vector<ExpandedPass> passes;
  std::vector<std::string> disabled;
  std::vector<VersionState> versions;
  std::vector<std::vector<int>> version_of;  // [resource][version number] -> index or -1
  std::vector<int> order;                    // expanded pass indices, execution order
  std::vector<VersionGroup> groups;
  CompiledPlan plan;

  void error(GraphErrorCode code, const std::string& location, std::string message);
  int find_resource(std::string_view name) const;
  // A condition evaluate_conditions saw; "" always holds.
  bool holds(std::string_view condition) const;
  // Index of (resource, version), created on first use.
  int version_index(int resource, int version);
  int existing_version(int resource, int version) const;
};

// The version a ping-pong write (SlotDecl::ping_pong) shares its texture with: two versions
// before the one it writes; -1 for any other use or when there is none.
int ping_pong_partner(const CompileState& s, const ResourceUse& use);

// Where the graph declares parameter `name`, for messages: "/parameters/N" in a file, else its name.
std::string param_location(const CompileState& s, const std::string& name);  // validate.cpp

// The stages, in the order compile() runs them; compile.cpp says what each decides, and each
// lives in the file of its name.
// Before CompileState exists: a copy of the graph with each chosen format set (nullopt when no
// resource chooses one); errors name the resource's format.
std::optional<GraphDesc> choose_formats(const GraphDesc& graph, const ParameterSet& params,
                                        GraphErrors& errors);  // formats.cpp
void index_resources(CompileState& s);              // index.cpp
void evaluate_conditions(CompileState& s);          // conditions.cpp
void bind_passes(CompileState& s);                  // bind.cpp
void validate_declarations(CompileState& s);        // validate.cpp, validate_parameters.cpp
// Part of validate_declarations: what no single pass shows (graph parameters that reach nothing,
// names taken from the frame, exposures compile() was given unresolved).
void validate_parameter_graph(CompileState& s);      // validate_parameters.cpp
void expand_passes(CompileState& s);                // expand.cpp
void resolve_versions(CompileState& s);             // versions.cpp
void cull_passes(CompileState& s);                  // cull.cpp
void order_passes(CompileState& s);                 // order.cpp
void compute_lifetimes(CompileState& s);            // lifetimes.cpp
void assign_physical_resources(CompileState& s);    // assign.cpp
void build_plan(CompileState& s);                   // build_plan.cpp
void plan_barriers(CompileState& s);                // barriers.cpp
void count_traffic(CompileState& s);                // traffic.cpp

}  // namespace penumbra::graph::detail
