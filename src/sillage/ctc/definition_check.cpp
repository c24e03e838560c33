#include "sillage/ctc/definition_check.h"

#include <unordered_set>

#include "sillage/interval/elementary.h"

namespace sillage {

namespace {

bool is_partial(const ExprNode& node) {
  switch (node.op) {
    case Op::Sqrt: case Op::Log: case Op::Div: case Op::Pow: case Op::Tan:
    case Op::Asin: case Op::Acos: case Op::Atan2:
      return true;
    case Op::PowInt: return node.n < 0;
    case Op::Root: return node.n <= 0 || node.n % 2 == 0;
    default: return false;
  }
}

}  // namespace

DefinitionCheck::DefinitionCheck(const Function& f) {
  std::vector<ExprVar> vars;
  for (const auto& name : f.var_names()) vars.emplace_back(name);
  std::unordered_set<const ExprNode*> seen;
  std::vector<Expr> stack(f.exprs().begin(), f.exprs().end());
  while (!stack.empty()) {
    const Expr e = stack.back();
    stack.pop_back();
    if (!seen.insert(e.get()).second) continue;
    const ExprNode& node = e.node();
    if (is_partial(node)) {
      Condition c{node.op, node.n, {}};
      for (const auto& a : node.args) c.args.emplace_back(vars, a);
      conditions_.push_back(std::move(c));
    }
    for (const auto& a : node.args) stack.push_back(a);
  }
}

bool DefinitionCheck::defined_on(const IntervalVector& x) const {
  if (x.is_empty()) return true;
  for (const auto& c : conditions_) {
    const Interval a = c.args[0].eval(x);
    if (a.is_empty()) return false;  // nothing proven about this operand
    bool ok = false;
    switch (c.op) {
      case Op::Sqrt: ok = a.lb() >= 0; break;
      case Op::Log: ok = a.lb() > 0; break;
      case Op::Pow: ok = a.lb() > 0; break;  // x^y = exp(y log x)
      case Op::Div: {
        const Interval d = c.args[1].eval(x);
        ok = !d.is_empty() && !d.contains(0.0);
        break;
      }
      case Op::PowInt: ok = !a.contains(0.0); break;        // negative exponent
      case Op::Root: ok = c.n > 0 && a.lb() >= 0; break;    // even order
      case Op::Tan: {
        const Interval cs = cos(a);
        ok = !cs.is_empty() && !cs.contains(0.0);
        break;
      }
      case Op::Asin: case Op::Acos: ok = a.is_subset(Interval(-1.0, 1.0)); break;
      case Op::Atan2: {
        const Interval b = c.args[1].eval(x);
        ok = !b.is_empty() && !(a.contains(0.0) && b.contains(0.0));
        break;
      }
      default: ok = false;
    }
    if (!ok) return false;
  }
  return true;
}

}  // namespace sillage
