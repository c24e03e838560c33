// Infix printing of expressions with the fewest parentheses that the parser
// reads back into the same DAG.
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "sillage/expr/expr.h"
#include "sillage/expr/literal.h"

namespace sillage {
namespace {

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

// A piece of output: a node to print (in parentheses when its precedence is
// below min_prec) or a fixed text. An explicit stack instead of recursion:
// long chains of operations must not exhaust the call stack.
struct Piece {
  const ExprNode* node;
  int min_prec;
  std::string text;
};

void print(std::ostream& os, const ExprNode& root) {
  std::vector<Piece> stack{{&root, 0, {}}};
  auto text = [&](std::string t) { stack.push_back({nullptr, 0, std::move(t)}); };
  auto node = [&](const Expr& a, int p) { stack.push_back({a.get(), p, {}}); };
  while (!stack.empty()) {
    Piece piece = std::move(stack.back());
    stack.pop_back();
    if (!piece.node) {
      os << piece.text;
      continue;
    }
    const ExprNode& e = *piece.node;
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
        node(e.args[1], prec(e) + 1);  // a - (b - c) keeps its parentheses
        text(std::string(" ").append(op_name(e.op)).append(" "));
        node(e.args[0], prec(e));
        break;
      case Op::Neg:
        node(e.args[0], kUnary);
        text("-");
        break;
      case Op::Sqr:
      case Op::PowInt:
        text(std::string("^").append(std::to_string(e.op == Op::Sqr ? 2 : e.n)));
        node(e.args[0], kAtom);
        break;
      case Op::Root:
        text(std::string(", ").append(std::to_string(e.n)).append(")"));
        node(e.args[0], 0);
        text("root(");
        break;
      default:
        text(")");
        for (std::size_t i = e.args.size(); i-- > 0;) {
          node(e.args[i], 0);
          if (i) text(", ");
        }
        text(std::string(op_name(e.op)).append("("));
    }
  }
}

}  // namespace

std::ostream& operator<<(std::ostream& os, const Expr& e) {
  print(os, e.node());
  return os;
}

std::string Expr::str() const {
  std::ostringstream os;
  os << *this;
  return os.str();
}

}  // namespace sillage
