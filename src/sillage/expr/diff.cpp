// Derivative rules. Non-smooth operations get a derivative enclosing their
// generalized (Clarke) gradient: d|a| = sign(a) da (sign([-,+]) = [-1, 1]),
// d min(a, b) = (da + db - sign(a - b)(da - db)) / 2. sign is discontinuous:
// its derivative 0 is only used where the mean-value form checks 0 is not in
// the operand (see Tape::forward_in_domain).
#include "sillage/expr/diff.h"

#include <unordered_map>

#include "sillage/expr/tape.h"

namespace sillage::detail {
namespace {

bool is_value(const Expr& e, double c) { return e.is_const() && e.node().value == Interval(c); }

Expr s_neg(const Expr& a) {
  if (is_value(a, 0)) return a;
  if (a.op() == Op::Neg) return a.node().args[0];
  return -a;
}
Expr s_add(const Expr& a, const Expr& b) {
  if (is_value(a, 0)) return b;
  if (is_value(b, 0)) return a;
  return a + b;
}
Expr s_sub(const Expr& a, const Expr& b) {
  if (is_value(b, 0)) return a;
  if (is_value(a, 0)) return s_neg(b);
  if (a == b) return Expr(0.0);
  return a - b;
}
Expr s_mul(const Expr& a, const Expr& b) {
  if (is_value(a, 0) || is_value(b, 0)) return Expr(0.0);
  if (is_value(a, 1)) return b;
  if (is_value(b, 1)) return a;
  if (is_value(a, -1)) return s_neg(b);
  if (is_value(b, -1)) return s_neg(a);
  return a * b;
}
Expr s_div(const Expr& a, const Expr& b) {
  if (is_value(a, 0)) return a;
  if (is_value(b, 1)) return a;
  return a / b;
}

// d f given the node f, its operands and their derivatives.
Expr rule(const Expr& f, const Expr& da, const Expr& db) {
  const ExprNode& node = f.node();
  const Expr& a = node.args[0];
  switch (node.op) {
    case Op::Add: return s_add(da, db);
    case Op::Sub: return s_sub(da, db);
    case Op::Mul: return s_add(s_mul(da, node.args[1]), s_mul(a, db));
    case Op::Div: return s_div(s_sub(da, s_mul(f, db)), node.args[1]);
    case Op::Neg: return s_neg(da);
    case Op::Sqr: return s_mul(s_mul(Expr(2.0), a), da);
    case Op::Sqrt: return s_div(da, s_mul(Expr(2.0), f));
    case Op::PowInt: return s_mul(s_mul(Expr(static_cast<double>(node.n)), pow(a, node.n - 1)), da);
    case Op::Pow: {
      const Expr& b = node.args[1];
      return s_mul(f, s_add(s_mul(db, log(a)), s_div(s_mul(b, da), a)));
    }
    case Op::Root: return s_div(da, s_mul(Expr(static_cast<double>(node.n)), pow(f, node.n - 1)));
    case Op::Exp: return s_mul(f, da);
    case Op::Log: return s_div(da, a);
    case Op::Sin: return s_mul(cos(a), da);
    case Op::Cos: return s_neg(s_mul(sin(a), da));
    case Op::Tan: return s_mul(Expr(1.0) + sqr(f), da);
    case Op::Asin: return s_div(da, sqrt(Expr(1.0) - sqr(a)));
    case Op::Acos: return s_neg(s_div(da, sqrt(Expr(1.0) - sqr(a))));
    case Op::Atan: return s_div(da, Expr(1.0) + sqr(a));
    case Op::Atan2: {  // f = atan2(a = y, b = x)
      const Expr& b = node.args[1];
      return s_div(s_sub(s_mul(b, da), s_mul(a, db)), sqr(a) + sqr(b));
    }
    case Op::Sinh: return s_mul(cosh(a), da);
    case Op::Cosh: return s_mul(sinh(a), da);
    case Op::Tanh: return s_mul(Expr(1.0) - sqr(f), da);
    case Op::Abs: return s_mul(sign(a), da);
    case Op::Min:
    case Op::Max: {
      if (da == db) return da;
      const Expr s = s_mul(sign(a - node.args[1]), s_sub(da, db));
      const Expr sum = s_add(da, db);
      return s_mul(Expr(0.5), node.op == Op::Min ? s_sub(sum, s) : s_add(sum, s));
    }
    case Op::Sign:
    case Op::Const:
    case Op::Var: break;
  }
  return Expr(0.0);
}

// d/dv of every node of `order` (operands first), in a map node -> derivative.
std::unordered_map<const ExprNode*, Expr> sweep(const std::vector<Expr>& order, const ExprVar& v) {
  std::unordered_map<const ExprNode*, Expr> d;
  const Expr zero(0.0), one(1.0);
  for (const Expr& e : order) {
    const ExprNode& node = e.node();
    if (node.op == Op::Const) {
      d.emplace(e.get(), zero);
    } else if (node.op == Op::Var) {
      d.emplace(e.get(), node.name == v.name() ? one : zero);
    } else {
      const Expr& da = d.at(node.args[0].get());
      const Expr& db = node.args.size() > 1 ? d.at(node.args[1].get()) : zero;
      // Operands that do not depend on v make f constant in v.
      d.emplace(e.get(), is_value(da, 0) && is_value(db, 0) ? zero : rule(e, da, db));
    }
  }
  return d;
}

}  // namespace

Expr diff(const Expr& e, const ExprVar& v) { return sweep(detail::topological_order({e}), v).at(e.get()); }

std::vector<Expr> jacobian_exprs(const std::vector<Expr>& es, const std::vector<ExprVar>& vars) {
  const std::vector<Expr> order = detail::topological_order(es);
  std::vector<Expr> jac(es.size() * vars.size(), Expr(0.0));
  for (std::size_t j = 0; j < vars.size(); ++j) {
    const auto d = sweep(order, vars[j]);
    for (std::size_t i = 0; i < es.size(); ++i) jac[i * vars.size() + j] = d.at(es[i].get());
  }
  return jac;
}

}  // namespace sillage::detail
