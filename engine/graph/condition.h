#pragma once
// The tiny `enabled` condition language of a pass. Grammar (whitespace ignored):
//
//   or      := and ( "||" and )*
//   and     := unary ( "&&" unary )*
//   unary   := "!" unary | compare
//   compare := operand ( ("==" | "!=") operand )?
//   operand := "$" name | "true" | "false" | integer | '"' string '"' | "(" or ")"
//
// A bare "$x" must name a bool parameter; "==" / "!=" compare a parameter with a literal of
// its type (enum parameters with a "string"). Examples: "$use_blur", "!$x",
// "$variant == \"mask\"", "$a && ($b || $c)".
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/parameters.h"
#include "util/error.h"

namespace penumbra::graph {

class Condition {
 public:
  // Always-true condition (an empty `enabled`).
  Condition() = default;
  static Result<Condition> parse(std::string_view text);
  // Type-checks against the parameter descriptions (unknown $name, wrong type).
  Status check(const ParameterSet& params) const;
  bool evaluate(const ParameterSet& params) const;  // call check() first
  const std::vector<std::string>& references() const { return references_; }

  struct Node;

 private:
  std::shared_ptr<const Node> root_;  // null: always true
  std::vector<std::string> references_;
};

}  // namespace penumbra::graph
