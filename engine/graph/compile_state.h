#pragma once
// Internal to the compiler (not installed): the state the stages of compile() pass along.
// Names become indices once (index_resources) so the later stages touch no strings.
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "graph/compiler.h"

namespace penumbra::graph::detail {

inline constexpr int kMaxVersion = 1024;

struct ResourceUse {
  const SlotDecl* slot = nullptr;
  const SlotBinding* binding = nullptr;
  int resource = -1;
  int read_version = -1;   // version index into CompileState::versions
  int write_version = -1;
};

struct ExpandedPass {
  const PassDecl* decl = nullptr;
  const PassTypeDecl* type = nullptr;
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
  const GraphDesc& graph;
  const PassTypeRegistry& registry;
  const ParameterSet& params;
  CompileSettings settings;
  CompileOptions options;
  GraphErrors errors;

  std::unordered_map<std::string_view, int> resource_index;
  std::vector<int> width, height;  // resolved texture sizes per resource
  std::vector<ExpandedPass> passes;
  std::vector<std::string> disabled;
  std::vector<VersionState> versions;
  std::vector<std::vector<int>> version_of;  // [resource][version number] -> index or -1
  std::vector<int> order;                    // expanded pass indices, execution order
  std::vector<VersionGroup> groups;
  CompiledPlan plan;

  void error(GraphErrorCode code, const std::string& location, std::string message);
  int find_resource(std::string_view name) const;
  // Index of (resource, version), created on first use.
  int version_index(int resource, int version);
  int existing_version(int resource, int version) const;
};

// The stages, in the order compile() runs them (compile.cpp documents each).
void index_resources(CompileState& s);
void validate_declarations(CompileState& s);
void expand_passes(CompileState& s);
void resolve_versions(CompileState& s);
void cull_passes(CompileState& s);
void order_passes(CompileState& s);
void compute_lifetimes(CompileState& s);
void assign_physical_resources(CompileState& s);
void plan_barriers(CompileState& s);
void build_plan(CompileState& s);

}  // namespace penumbra::graph::detail
