#include "graph/condition.h"

#include <cctype>

namespace penumbra::graph {

struct Condition::Node {
  enum class Kind { literal, param, negate, all, any, equal, not_equal } kind;
  ParamValue literal;
  std::string name;                                // param
  std::vector<std::shared_ptr<const Node>> children;  // negate: 1, equal/not_equal: 2, all/any: n
};

namespace {

using NodePtr = std::shared_ptr<const Condition::Node>;
using Kind = Condition::Node::Kind;

// Recursive descent over the grammar in condition.h. Only "(" and "!" recurse, and they are
// bounded by kMaxConditionDepth; operator chains are loops that build one n-ary node.
class Parser {
 public:
  explicit Parser(std::string_view t) : text_(t) {}

  Result<NodePtr> parse_all(std::vector<std::string>& refs) {
    refs_ = &refs;
    NodePtr n = parse_or();
    skip_space();
    if (!error_.empty()) return fail(error_);
    if (pos_ != text_.size()) return fail("unexpected '" + shortened(text_.substr(pos_)) + "'");
    return n;
  }

 private:
  Error fail(const std::string& what) {
    return make_error("condition \"" + shortened(text_) + "\": " + what + " at column " +
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
  static NodePtr make(Kind k, std::vector<NodePtr> children) {
    return std::make_shared<Condition::Node>(Condition::Node{k, false, "", std::move(children)});
  }
  NodePtr chain(Kind k, std::string_view op, NodePtr (Parser::*next)()) {
    std::vector<NodePtr> terms{(this->*next)()};
    while (error_.empty() && eat(op)) terms.push_back((this->*next)());
    return terms.size() == 1 ? terms.front() : make(k, std::move(terms));
  }
  NodePtr parse_or() { return chain(Kind::any, "||", &Parser::parse_and); }
  NodePtr parse_and() { return chain(Kind::all, "&&", &Parser::parse_unary); }
  bool enter() {
    if (++depth_ <= kMaxConditionDepth) return true;
    error_ = "nested deeper than " + std::to_string(kMaxConditionDepth) + " levels";
    return false;
  }
  // The depth counts "!" and "(" as written (each enters once), so the limit reads as the text.
  NodePtr parse_unary() {
    NodePtr n;
    if (eat("!")) {
      if (!enter()) return nullptr;
      n = make(Kind::negate, {parse_unary()});
      --depth_;
    } else {
      n = parse_operand();
      if (error_.empty() && eat("==")) n = make(Kind::equal, {n, parse_operand()});
      else if (error_.empty() && eat("!=")) n = make(Kind::not_equal, {n, parse_operand()});
    }
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
    auto node = std::make_shared<Condition::Node>(Condition::Node{Kind::literal, false, "", {}});
    if (c == '(') {
      ++pos_;
      if (!enter()) return nullptr;
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
        error_ = "bad integer '" + shortened(digits) + "'";
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

using Problem = std::optional<ConditionProblem>;

Problem problem(ConditionProblem::Kind kind, std::string message) {
  return ConditionProblem{kind, std::move(message)};
}

// The type of an operand of == / != (index into ParamValue), or a problem.
Problem operand_type(const Condition::Node& n, const ParameterSet& params, size_t& type) {
  if (n.kind == Kind::literal) {
    type = n.literal.index();
    return std::nullopt;
  }
  if (n.kind == Kind::param) {
    const ParamDesc* d = params.find(n.name);
    if (!d) return problem(ConditionProblem::Kind::unknown_parameter, "unknown parameter '$" + n.name + "'");
    type = d->default_value.index();
    return std::nullopt;
  }
  type = ParamValue(false).index();  // a parenthesised boolean expression
  return std::nullopt;
}

Problem check_param(const ParamDesc* d, const std::string& name) {
  if (!d) return problem(ConditionProblem::Kind::unknown_parameter, "unknown parameter '$" + name + "'");
  if (!d->structural)
    return problem(ConditionProblem::Kind::not_structural,
                   "'$" + name + "' is not structural: the plan would not be rebuilt when it "
                   "changes; declare it \"structural\": true");
  return std::nullopt;
}

Problem check_node(const Condition::Node& n, const ParameterSet& params) {
  switch (n.kind) {
    case Kind::literal:
      if (!std::holds_alternative<bool>(n.literal))
        return problem(ConditionProblem::Kind::wrong_type,
                       "a non-bool literal " + shortened(param_value_to_string(n.literal)) +
                           " used as a condition");
      return std::nullopt;
    case Kind::param: {
      const ParamDesc* d = params.find(n.name);
      if (d && d->type != ParamType::boolean)
        return problem(ConditionProblem::Kind::wrong_type,
                       "'$" + n.name + "' is " + param_type_name(d->type) +
                           ", not bool; compare it (e.g. $" + n.name + " == ...)");
      return check_param(d, n.name);
    }
    case Kind::negate:
    case Kind::all:
    case Kind::any:
      for (const NodePtr& c : n.children)
        if (Problem p = check_node(*c, params)) return p;
      return std::nullopt;
    case Kind::equal:
    case Kind::not_equal: {
      size_t types[2] = {0, 0};
      for (int i = 0; i < 2; ++i) {
        const Condition::Node& side = *n.children[i];
        if (side.kind == Kind::param)
          if (Problem p = check_param(params.find(side.name), side.name)) return p;
        if (side.kind != Kind::param && side.kind != Kind::literal)
          if (Problem p = check_node(side, params)) return p;
        if (Problem p = operand_type(side, params, types[i])) return p;
      }
      if (types[0] != types[1])
        return problem(ConditionProblem::Kind::wrong_type, "comparison of values of different types");
      // An enum compared with a string that is none of its options can never hold: a typo.
      for (int i = 0; i < 2; ++i) {
        const Condition::Node& side = *n.children[i];
        const Condition::Node& other = *n.children[1 - i];
        const ParamDesc* d = side.kind == Kind::param ? params.find(side.name) : nullptr;
        if (!d || d->type != ParamType::enumeration || other.kind != Kind::literal) continue;
        const std::string& value = std::get<std::string>(other.literal);
        bool known = false;
        std::string options;
        for (const std::string& o : d->options) {
          known = known || o == value;
          options += (options.empty() ? "" : ", ") + o;
        }
        if (!known)
          return problem(ConditionProblem::Kind::wrong_type,
                         "\"" + shortened(value) + "\" is not an option of '$" + side.name +
                             "' (" + options + ")");
      }
      return std::nullopt;
    }
  }
  return std::nullopt;
}

ParamValue operand_value(const Condition::Node& n, const ParameterSet& params);

bool eval_node(const Condition::Node& n, const ParameterSet& params) {
  switch (n.kind) {
    case Kind::literal: return std::holds_alternative<bool>(n.literal) && std::get<bool>(n.literal);
    case Kind::param: return params.get_bool(n.name);
    case Kind::negate: return !eval_node(*n.children[0], params);
    case Kind::all:
      for (const NodePtr& c : n.children)
        if (!eval_node(*c, params)) return false;
      return true;
    case Kind::any:
      for (const NodePtr& c : n.children)
        if (eval_node(*c, params)) return true;
      return false;
    case Kind::equal: return operand_value(*n.children[0], params) == operand_value(*n.children[1], params);
    case Kind::not_equal: return operand_value(*n.children[0], params) != operand_value(*n.children[1], params);
  }
  return false;
}

ParamValue operand_value(const Condition::Node& n, const ParameterSet& params) {
  if (n.kind == Kind::literal) return n.literal;
  if (n.kind == Kind::param) {
    const ParamValue* v = params.get(n.name);
    return v ? *v : ParamValue{false};
  }
  return eval_node(n, params);
}

}  // namespace

Result<Condition> Condition::parse(std::string_view text) {
  Condition c;
  bool blank = true;
  for (char ch : text) blank = blank && std::isspace(static_cast<unsigned char>(ch));
  if (blank) return c;
  if (text.size() > kMaxConditionLength)
    return make_error("condition \"" + shortened(text) + "\" is " + std::to_string(text.size()) +
                      " characters long; at most " + std::to_string(kMaxConditionLength));
  Parser parser(text);
  Result<NodePtr> root = parser.parse_all(c.references_);
  if (!root) return root.error();
  c.root_ = *root;
  return c;
}

std::optional<ConditionProblem> Condition::check(const ParameterSet& params) const {
  return root_ ? check_node(*root_, params) : std::nullopt;
}

bool Condition::evaluate(const ParameterSet& params) const {
  return root_ ? eval_node(*root_, params) : true;
}

std::string condition_and(std::string_view a, std::string_view b) {
  if (a.empty()) return std::string(b);
  if (b.empty()) return std::string(a);
  return "(" + std::string(a) + ") && (" + std::string(b) + ")";
}

}  // namespace penumbra::graph
