#include "graph/condition.h"

#include <cctype>

namespace penumbra::graph {

struct Condition::Node {
  enum class Kind { literal, param, negate, both, either, equal, not_equal } kind;
  ParamValue literal;
  std::string name;  // param
  std::shared_ptr<const Node> a, b;
};

namespace {

using NodePtr = std::shared_ptr<const Condition::Node>;
using Kind = Condition::Node::Kind;

// Recursive descent over the grammar in condition.h; depth is bounded so hostile input
// ("((((((...") cannot overflow the stack.
class Parser {
 public:
  explicit Parser(std::string_view t) : text_(t) {}

  Result<NodePtr> parse_all(std::vector<std::string>& refs) {
    refs_ = &refs;
    NodePtr n = parse_or();
    skip_space();
    if (!error_.empty()) return fail(error_);
    if (pos_ != text_.size()) return fail("unexpected '" + std::string(text_.substr(pos_)) + "'");
    return n;
  }

 private:
  Error fail(const std::string& what) {
    return make_error("condition \"" + std::string(text_) + "\": " + what + " at column " +
                      std::to_string(pos_ + 1));
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool eat(std::string_view token) {
    skip_space();
    if (text_.substr(pos_, token.size()) == token) {
      pos_ += token.size();
      return true;
    }
    return false;
  }
  NodePtr make(Kind k, NodePtr a = nullptr, NodePtr b = nullptr) {
    return std::make_shared<Condition::Node>(Condition::Node{k, false, "", a, b});
  }
  NodePtr parse_or() {
    NodePtr n = parse_and();
    while (error_.empty() && eat("||")) n = make(Kind::either, n, parse_and());
    return n;
  }
  NodePtr parse_and() {
    NodePtr n = parse_unary();
    while (error_.empty() && eat("&&")) n = make(Kind::both, n, parse_unary());
    return n;
  }
  NodePtr parse_unary() {
    if (++depth_ > 64) {
      error_ = "nested too deeply";
      return nullptr;
    }
    NodePtr n;
    if (eat("!") ) {
      n = make(Kind::negate, parse_unary());
    } else {
      n = parse_operand();
      if (error_.empty() && eat("==")) n = make(Kind::equal, n, parse_operand());
      else if (error_.empty() && eat("!=")) n = make(Kind::not_equal, n, parse_operand());
    }
    --depth_;
    return n;
  }
  NodePtr parse_operand() {
    skip_space();
    if (!error_.empty()) return nullptr;
    if (pos_ >= text_.size()) {
      error_ = "expected an operand";
      return nullptr;
    }
    char c = text_[pos_];
    auto node = std::make_shared<Condition::Node>(Condition::Node{Kind::literal, false, "", {}, {}});
    if (c == '(') {
      ++pos_;
      if (++depth_ > 64) {
        error_ = "nested too deeply";
        return nullptr;
      }
      NodePtr inner = parse_or();
      --depth_;
      if (error_.empty() && !eat(")")) error_ = "expected ')'";
      return inner;
    }
    if (c == '$') {
      size_t start = ++pos_;
      while (pos_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
        ++pos_;
      if (pos_ == start) {
        error_ = "expected a parameter name after '$'";
        return nullptr;
      }
      node->kind = Kind::param;
      node->name = std::string(text_.substr(start, pos_ - start));
      refs_->push_back(node->name);
      return node;
    }
    if (c == '"') {
      size_t end = text_.find('"', pos_ + 1);
      if (end == std::string_view::npos) {
        error_ = "unterminated string";
        return nullptr;
      }
      node->literal = std::string(text_.substr(pos_ + 1, end - pos_ - 1));
      pos_ = end + 1;
      return node;
    }
    if (eat("true")) { node->literal = true; return node; }
    if (eat("false")) { node->literal = false; return node; }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '-') {
      size_t start = pos_++;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      std::string digits(text_.substr(start, pos_ - start));
      if (digits == "-" || digits.size() > 10) {
        error_ = "bad integer '" + digits + "'";
        return nullptr;
      }
      long long v = std::stoll(digits);
      if (v < INT32_MIN || v > INT32_MAX) {
        error_ = "integer out of range";
        return nullptr;
      }
      node->literal = static_cast<int>(v);
      return node;
    }
    error_ = "expected $name, true, false, a number or a \"string\"";
    return nullptr;
  }

  std::string_view text_;
  size_t pos_ = 0;
  int depth_ = 0;
  std::string error_;
  std::vector<std::string>* refs_ = nullptr;
};

// The value type an operand has: index into ParamValue, or -1 for a failed lookup.
int operand_type(const Condition::Node& n, const ParameterSet& params) {
  if (n.kind == Kind::literal) return static_cast<int>(n.literal.index());
  if (n.kind == Kind::param) {
    const ParamDesc* d = params.find(n.name);
    if (!d) return -1;
    return static_cast<int>(d->default_value.index());
  }
  return 0;  // boolean sub-expression
}

Status check_node(const Condition::Node& n, const ParameterSet& params) {
  switch (n.kind) {
    case Kind::literal:
      if (!std::holds_alternative<bool>(n.literal))
        return make_error("a non-bool literal " + param_value_to_string(n.literal) +
                          " used as a condition");
      return {};
    case Kind::param: {
      const ParamDesc* d = params.find(n.name);
      if (!d) return make_error("unknown parameter '$" + n.name + "'");
      if (d->type != ParamType::boolean)
        return make_error("'$" + n.name + "' is " + param_type_name(d->type) +
                          ", not bool; compare it (e.g. $" + n.name + " == ...)");
      return {};
    }
    case Kind::negate: return check_node(*n.a, params);
    case Kind::both:
    case Kind::either:
      if (Status s = check_node(*n.a, params); !s) return s;
      return check_node(*n.b, params);
    case Kind::equal:
    case Kind::not_equal: {
      for (const auto* side : {n.a.get(), n.b.get()})
        if (side->kind == Kind::param && !params.find(side->name))
          return make_error("unknown parameter '$" + side->name + "'");
      if (operand_type(*n.a, params) != operand_type(*n.b, params))
        return make_error("comparison of values of different types");
      return {};
    }
  }
  return {};
}

ParamValue operand_value(const Condition::Node& n, const ParameterSet& params) {
  if (n.kind == Kind::param) {
    const ParamValue* v = params.get(n.name);
    return v ? *v : ParamValue{false};
  }
  return n.literal;
}

bool eval_node(const Condition::Node& n, const ParameterSet& params) {
  switch (n.kind) {
    case Kind::literal: return std::holds_alternative<bool>(n.literal) && std::get<bool>(n.literal);
    case Kind::param: return params.get_bool(n.name);
    case Kind::negate: return !eval_node(*n.a, params);
    case Kind::both: return eval_node(*n.a, params) && eval_node(*n.b, params);
    case Kind::either: return eval_node(*n.a, params) || eval_node(*n.b, params);
    case Kind::equal: return operand_value(*n.a, params) == operand_value(*n.b, params);
    case Kind::not_equal: return operand_value(*n.a, params) != operand_value(*n.b, params);
  }
  return false;
}

}  // namespace

Result<Condition> Condition::parse(std::string_view text) {
  Condition c;
  bool blank = true;
  for (char ch : text) blank = blank && std::isspace(static_cast<unsigned char>(ch));
  if (blank) return c;
  Parser parser(text);
  Result<NodePtr> root = parser.parse_all(c.references_);
  if (!root) return root.error();
  c.root_ = *root;
  return c;
}

Status Condition::check(const ParameterSet& params) const {
  return root_ ? check_node(*root_, params) : Status{};
}

bool Condition::evaluate(const ParameterSet& params) const {
  return root_ ? eval_node(*root_, params) : true;
}

}  // namespace penumbra::graph
