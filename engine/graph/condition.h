#pragma once
// The tiny condition language of a pass's `enabled` and of a binding's `when` (graph_desc.h).
// Grammar (whitespace ignored):
//
//   or      := and ( "||" and )*
//   and     := unary ( "&&" unary )*
//   unary   := "!" unary | compare
//   compare := operand ( ("==" | "!=") operand )?
//   operand := "$" name | "true" | "false" | integer | '"' string '"' | "(" or ")"
//
// A bare "$x" must name a bool parameter; "==" / "!=" compare a parameter with a literal of
// its type (enum parameters with one of their options as a "string"). Every parameter a
// condition reads must be structural: the compiled plan is static per parameter set, so a
// change of it has to recompile. Examples: "$use_blur", "!$x", "$variant == \"mask\"",
// "$a && ($b || $c)".
//
//   Result<Condition> c = Condition::parse("$variant == \"mask\" && !$checkerboard");
//   if (auto problem = c->check(params)) report(problem->message);
//   else if (c->evaluate(params)) ...
//
// Chains of || and && are n-ary nodes, so neither parsing nor checking nor evaluating recurses
// along a chain: only parentheses and "!" nest, and they are bounded (kMaxConditionDepth).
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "graph/parameters.h"
#include "util/error.h"

namespace penumbra::graph {

inline constexpr int kMaxConditionDepth = 64;        // nested "(" and "!"
inline constexpr size_t kMaxConditionLength = 4096;  // characters of one condition

struct ConditionProblem {
  enum class Kind { syntax, unknown_parameter, wrong_type, not_structural } kind;
  std::string message;
};

class Condition {
 public:
  // Always-true condition (an empty `enabled` / `when`).
  Condition() = default;
  // Errors are ConditionProblem::Kind::syntax; the message quotes the text (shortened) and
  // names the column.
  static Result<Condition> parse(std::string_view text);
  // Type-checks against the parameter descriptions: unknown $name, wrong type, an enum compared
  // with a string that is not one of its options, a parameter that is not structural.
  std::optional<ConditionProblem> check(const ParameterSet& params) const;
  bool evaluate(const ParameterSet& params) const;  // call check() first
  const std::vector<std::string>& references() const { return references_; }

  struct Node;

 private:
  std::shared_ptr<const Node> root_;  // null: always true
  std::vector<std::string> references_;
};

// "a" && "b" as condition text (either may be empty = true), for conditions composed from
// nested choices.
std::string condition_and(std::string_view a, std::string_view b);

}  // namespace penumbra::graph
