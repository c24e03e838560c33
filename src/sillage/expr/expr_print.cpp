// Infix printing of expressions with the fewest parentheses that the parser
// reads back into the same DAG.
//
// Sharing: a DAG of n nodes may unfold into a tree of 2^n nodes (e = x;
// e = e*e + 1 repeated), so a shared sub-expression whose text is longer than
// kInlineMax characters is printed once, named by a let-binding:
//   let a = x * x + 1; b = a * a + 1 in b * b + 1
// Shorter ones (x - 1, sin(x)) stay inline, where they read best. The output
// is linear in the size of the DAG. A sub-expression nested deeper than
// kMaxNesting levels (as parser.cpp counts them) is named as well, so that
// the text always parses back (the parser stops at 500 levels).
#include <algorithm>
#include <ostream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "sillage/expr/expr.h"
#include "sillage/expr/literal.h"
#include "sillage/expr/parser.h"
#include "sillage/expr/tape.h"

namespace sillage {
namespace {

constexpr std::size_t kInlineMax = 8;
constexpr std::size_t kMaxNesting = 400;

enum Prec { kSum = 1, kProduct = 2, kUnary = 3, kPower = 4, kAtom = 5 };

int prec(const ExprNode& e) {
  switch (e.op) {
    case Op::Add:
    case Op::Sub: return kSum;
    case Op::Mul:
    case Op::Div: return kProduct;
    case Op::Neg: return kUnary;
    case Op::Sqr:
    case Op::PowInt: return kPower;
    case Op::Const: return detail::literal_str(e.value)[0] == '-' ? kUnary : kAtom;
    default: return kAtom;
  }
}

bool infix(const ExprNode& e) { return e.op == Op::Add || e.op == Op::Sub || e.op == Op::Mul || e.op == Op::Div; }

// Least precedence operand i of e may have without parentheses.
int operand_prec(const ExprNode& e, std::size_t i) {
  switch (e.op) {
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div: return prec(e) + (i == 1 ? 1 : 0);  // a - (b - c) keeps its parentheses
    case Op::Neg: return kUnary;
    case Op::Sqr:
    case Op::PowInt: return kAtom;
    default: return 0;
  }
}

// The text of e without its operands ("sin(, )" for sin(a)...).
std::size_t own_length(const ExprNode& e) {
  switch (e.op) {
    case Op::Const: return detail::literal_str(e.value).size();
    case Op::Var: return e.name.size();
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div: return 3;
    case Op::Neg: return 1;
    case Op::Sqr:
    case Op::PowInt: return 1 + std::to_string(e.op == Op::Sqr ? 2 : e.n).size();
    case Op::Root: return 8 + std::to_string(e.n).size();  // "root(" ", n" ")"
    default: return std::string(op_name(e.op)).size() + 2 * e.args.size();  // "f(" ", " ")"
  }
}

// Nesting levels (parser.cpp's DepthGuard) that e adds around an operand
// printed with or without parentheses: a call, a unary sign, parentheses.
std::size_t added_levels(const ExprNode& e, bool parenthesized) {
  const bool call = !(infix(e) || e.op == Op::Neg || e.op == Op::Sqr || e.op == Op::PowInt);
  return (parenthesized ? 1 : 0) + (call || e.op == Op::Neg ? 1 : 0);
}

// Names of the shared sub-expressions printed once.
using Names = std::unordered_map<const ExprNode*, std::string>;

// True if e prints with a sign first ("-2", "-x * y"): down the left
// operands printed without parentheses; a named node prints as its name.
bool leading_sign(const ExprNode* e, const Names& names) {
  for (;;) {
    if (names.count(e)) return false;
    if (prec(*e) == kUnary) return true;
    if (!infix(*e) || prec(*e->args[0].get()) < operand_prec(*e, 0)) return false;
    e = e->args[0].get();
  }
}

// Least precedence the child `a` at operand i of e may have without
// parentheses. A sign never follows an operator directly: "x - (-2)",
// "x * (-y * 2)" and "-(-x)", not "x - -2", which reads as a typo.
int needed_prec(const ExprNode& e, std::size_t i, const ExprNode& a, const Names& names) {
  const bool after_operator = e.op == Op::Neg || (i == 1 && infix(e));
  return after_operator && leading_sign(&a, names) ? kAtom : operand_prec(e, i);
}

// A piece of output: a node to print (in parentheses when its precedence is
// below min_prec) or a fixed text. An explicit stack instead of recursion:
// long chains of operations must not exhaust the call stack. Named nodes but
// the root print as their name.
struct Piece {
  const ExprNode* node;
  int min_prec;
  std::string text;
};

void print(std::ostream& os, const ExprNode& root, const Names& names) {
  std::vector<Piece> stack{{&root, 0, {}}};
  auto text = [&](std::string t) { stack.push_back({nullptr, 0, std::move(t)}); };
  auto node = [&](const ExprNode& e, std::size_t i) { stack.push_back({e.args[i].get(), needed_prec(e, i, e.args[i].node(), names), {}}); };
  while (!stack.empty()) {
    Piece piece = std::move(stack.back());
    stack.pop_back();
    if (!piece.node) {
      os << piece.text;
      continue;
    }
    const ExprNode& e = *piece.node;
    if (&e != &root) {
      if (auto it = names.find(&e); it != names.end()) {
        os << it->second;
        continue;
      }
    }
    if (prec(e) < piece.min_prec) {  // pushed in reverse: "(", e, ")"
      text(")");
      stack.push_back({&e, 0, {}});
      text("(");
      continue;
    }
    switch (e.op) {
      case Op::Const: os << detail::literal_str(e.value); break;
      case Op::Var: os << e.name; break;
      case Op::Add:
      case Op::Sub:
      case Op::Mul:
      case Op::Div:
        node(e, 1);
        text(std::string(" ").append(op_name(e.op)).append(" "));
        node(e, 0);
        break;
      case Op::Neg:
        node(e, 0);
        text("-");
        break;
      case Op::Sqr:
      case Op::PowInt:
        text(std::string("^").append(std::to_string(e.op == Op::Sqr ? 2 : e.n)));
        node(e, 0);
        break;
      case Op::Root:
        text(std::string(", ").append(std::to_string(e.n)).append(")"));
        node(e, 0);
        text("root(");
        break;
      default:
        text(")");
        for (std::size_t i = e.args.size(); i-- > 0;) {
          node(e, i);
          if (i) text(", ");
        }
        text(std::string(op_name(e.op)).append("("));
    }
  }
}

// a, b, ..., z, a1, ..., z1, a2, ...: the n-th name that is neither a
// variable of the expression nor reserved by the syntax.
class NameSource {
 public:
  explicit NameSource(std::unordered_set<std::string> taken) : taken_(std::move(taken)) {}
  std::string next() {
    for (;;) {
      std::string s(1, static_cast<char>('a' + k_ % 26));
      if (k_ >= 26) s += std::to_string(k_ / 26);
      ++k_;
      if (!taken_.count(s) && !detail::is_reserved_name(s)) return s;
    }
  }

 private:
  std::unordered_set<std::string> taken_;
  std::size_t k_ = 0;
};

// Chooses the let-bound nodes of `order` (operands first) and returns them in
// that order, with their names in `names`.
std::vector<const ExprNode*> choose_names(const std::vector<Expr>& order, const std::vector<Expr>& roots,
                                          const std::vector<std::string>& taken, Names& names) {
  std::unordered_map<const ExprNode*, std::size_t> uses, length, nesting;
  std::unordered_set<std::string> vars(taken.begin(), taken.end());
  for (const Expr& r : roots) ++uses[r.get()];
  for (const Expr& e : order) {
    for (const Expr& a : e.node().args) ++uses[a.get()];
    if (e.op() == Op::Var) vars.insert(e.node().name);
  }
  NameSource source(std::move(vars));
  std::vector<const ExprNode*> bound;
  for (const Expr& e : order) {
    const ExprNode& node = e.node();
    std::size_t n = own_length(node);
    // Own levels: the exponent of a power, the sign of a negative constant.
    std::size_t depth = node.op == Op::Sqr || node.op == Op::PowInt || prec(node) == kUnary ? 1 : 0;
    for (std::size_t i = 0; i < node.args.size(); ++i) {
      const ExprNode* a = node.args[i].get();
      if (auto it = names.find(a); it != names.end()) {
        n += it->second.size();
        depth = std::max(depth, added_levels(node, false));
      } else {
        const bool parenthesized = prec(*a) < needed_prec(node, i, *a, names);
        n += length[a] + (parenthesized ? 2 : 0);
        depth = std::max(depth, nesting[a] + added_levels(node, parenthesized));
      }
    }
    length[&node] = n;
    nesting[&node] = depth;
    if (!node.args.empty() && ((uses[&node] >= 2 && n > kInlineMax) || depth > kMaxNesting)) {
      names.emplace(&node, source.next());
      bound.push_back(&node);
    }
  }
  return bound;
}

}  // namespace

void print_exprs(std::ostream& os, const std::vector<Expr>& es, bool as_vector,
                 const std::vector<std::string>& taken) {
  Names names;
  const std::vector<const ExprNode*> bound = choose_names(detail::topological_order(es), es, taken, names);
  if (!bound.empty()) {
    os << "let ";
    for (std::size_t i = 0; i < bound.size(); ++i) {
      os << (i ? "; " : "") << names.at(bound[i]) << " = ";
      print(os, *bound[i], names);
    }
    os << " in ";
  }
  if (as_vector) os << '(';
  for (std::size_t i = 0; i < es.size(); ++i) {
    if (i) os << ", ";
    auto it = names.find(es[i].get());
    if (it != names.end()) {
      os << it->second;
    } else {
      print(os, es[i].node(), names);
    }
  }
  if (as_vector) os << ')';
}

std::ostream& operator<<(std::ostream& os, const Expr& e) {
  print_exprs(os, {e}, false);
  return os;
}

std::string Expr::str() const {
  std::ostringstream os;
  os << *this;
  return os.str();
}

}  // namespace sillage
