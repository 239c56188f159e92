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
//
// Binding rule (which binding a slot or parameter gets, for the current parameter values):
//  - A slot or parameter may have several bindings, each with a `when` condition on structural
//    parameters (condition.h); the first whose condition holds applies ("" always holds, so it
//    ends the list). None applying: the slot is unbound.
//  - A pass parameter with no applying binding takes the value of the graph parameter that
//    exposes it (ParamExposure), else the pass type's default. Nothing binds by name: a pass
//    parameter that shares a graph parameter's name but is bound to neither is an error.
//  - A `$`-bound parameter's graph declaration must fit the pass type's: range inside the pass
//    type's range, enum options among its options, the same unit where both name one.
#include <string>
#include <vector>

#include "graph/parameters.h"
#include "graph/resources.h"

namespace penumbra::graph {

inline constexpr int kMaxRepeat = 64;     // `repeat` count
inline constexpr int kMaxVersion = 1024;  // `name@N`, and versions a frame may write

// A slot bound to a resource; version -1 = implicit (see the rule above).
struct SlotBinding {
  std::string slot;
  std::string resource;  // "" (only with a `when`): the slot stays unbound when chosen
  int version = -1;
  std::string location;  // JSON pointer, e.g. "/passes/2/slots/input"
  std::string when;      // condition choosing this binding; "" = always
};

// A pass parameter: a constant, or a reference to a technique parameter ("$name").
struct ParamBinding {
  std::string name;
  ParamValue constant;
  std::string reference;  // technique parameter name without '$'; empty = constant
  std::string location;
  std::string when;       // condition choosing this binding; "" = always
  bool unbound = false;   // chosen, this binding leaves the parameter to its exposure or default
};

// Which fields of an exposing parameter's declaration the graph states itself; the others come
// from the pass type's declaration of the exposed parameter.
struct StatedFields {
  bool type = false, default_value = false, min = false, max = false, unit = false, description = false,
       options = false, step = false;
};

// A graph parameter that exposes a pass's parameter under its own name ("exposes": "pass.param",
// docs/graph-format.md "Parameters"): the pass parameter is described once, by its pass type;
// the graph parameter inherits the description and states only what it changes (typically the
// default). The exposure is also the pass parameter's binding.
struct ParamExposure {
  std::string parameter;   // the graph parameter
  std::string pass;        // a pass of this graph, by name
  std::string pass_param;  // a parameter of that pass's type
  std::string location;    // JSON pointer of the "exposes" key
  StatedFields stated;
  bool resolved = false;   // resolve_exposures() (exposures.h) filled in the description
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
  bool frame = false;           // one of the frame's own passes (gbuffer, lighting): no graph
                                // parameter may bind it or take one of its parameters' names
};

struct GraphDesc {
  std::string name;
  std::string description;              // one paragraph: what the technique is (CLI, sandbox)
  std::string source_file;              // for error messages; "" from C++
  std::vector<ParamDesc> parameters;    // the technique's parameters
  std::vector<ParamExposure> exposures; // parameters that expose a pass parameter
  std::vector<ResourceDecl> resources;
  std::vector<PassDecl> passes;
  std::vector<std::string> outputs;     // logical resource names (their final version)
};

}  // namespace penumbra::graph
