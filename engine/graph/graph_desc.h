#pragma once
// The declared render graph: what the JSON parser and the C++ builder (builder.h) both
// produce, and what compile() (compiler.h) consumes. Names are strings here only because the
// graph comes from files; the compiler turns them into indices once.
//
// Versioning rule (the one place it is written down in code; docs/graph-format.md too):
//  - Every write creates a version. Passes are considered in declaration order after
//    expansion: a repeated pass counts as N consecutive passes, a disabled pass is absent.
//  - A write binding "r" produces version (highest version of r declared so far) + 1.
//    "r@n" produces exactly version n; two passes producing one version is an error.
//  - A read binding "r" reads the latest version of r produced by a pass declared BEFORE
//    it; with none, version 0, which only imported and persistent resources have (provided
//    by the executor / last frame). "r@n" reads exactly version n (any producer position).
//  - A read_write binding "r" reads the latest version n and produces n+1 in place.
#include <string>
#include <vector>

#include "graph/parameters.h"
#include "graph/resources.h"

namespace penumbra::graph {

inline constexpr int kMaxRepeat = 64;

// A slot bound to a resource; version -1 = implicit (see the rule above).
struct SlotBinding {
  std::string slot;
  std::string resource;
  int version = -1;
  std::string location;  // JSON pointer, e.g. "/passes/2/slots/input"
};

// A pass parameter: a constant, or a reference to a technique parameter ("$name").
struct ParamBinding {
  std::string name;
  ParamValue constant;
  std::string reference;  // technique parameter name without '$'; empty = constant
  std::string location;
};

struct PassDecl {
  std::string type;
  std::string name;
  std::vector<SlotBinding> slots;
  std::vector<ParamBinding> params;
  std::string enabled;          // condition text (condition.h); empty = always
  int repeat = 1;               // used when repeat_reference is empty
  std::string repeat_reference; // technique parameter name without '$'
  bool side_effect = false;     // culling root even if nothing reads its outputs
  std::string location;         // JSON pointer, e.g. "/passes/2"
};

struct GraphDesc {
  std::string name;
  std::string source_file;              // for error messages; "" from C++
  std::vector<ParamDesc> parameters;    // the technique's parameters
  std::vector<ResourceDecl> resources;
  std::vector<PassDecl> passes;
  std::vector<std::string> outputs;     // logical resource names (their final version)
};

}  // namespace penumbra::graph
