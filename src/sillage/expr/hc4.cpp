// HC4-revise backward pass (thesis 2.3.1): from the output down to the
// variables, each node projects its (contracted) value onto its operands with
// the backward functions of backward.h. Operands are contracted on copies then
// intersected, so a node shared by several users (or used twice by one, as
// in x * x) receives the intersection of all its projections.
#include "sillage/expr/tape.h"
#include "sillage/interval/backward.h"

namespace sillage::detail {

namespace {

bool project(const Instr& in, const Interval& y, Interval& a, Interval& b) {
  switch (in.op) {
    case Op::Add: return bwd_add(y, a, b);
    case Op::Sub: return bwd_sub(y, a, b);
    case Op::Mul: return bwd_mul(y, a, b);
    case Op::Div: return bwd_div(y, a, b);
    case Op::Neg: return bwd_neg(y, a);
    case Op::Sqr: return bwd_sqr(y, a);
    case Op::Sqrt: return bwd_sqrt(y, a);
    case Op::PowInt: return in.n == 2 ? bwd_sqr(y, a) : bwd_pow(y, a, in.n);
    case Op::Pow: return bwd_pow(y, a, b);
    case Op::Root: return bwd_root(y, a, in.n);
    case Op::Exp: return bwd_exp(y, a);
    case Op::Log: return bwd_log(y, a);
    case Op::Sin: return bwd_sin(y, a);
    case Op::Cos: return bwd_cos(y, a);
    case Op::Tan: return bwd_tan(y, a);
    case Op::Asin: return bwd_asin(y, a);
    case Op::Acos: return bwd_acos(y, a);
    case Op::Atan: return bwd_atan(y, a);
    case Op::Atan2: return bwd_atan2(y, a, b);
    case Op::Sinh: return bwd_sinh(y, a);
    case Op::Cosh: return bwd_cosh(y, a);
    case Op::Tanh: return bwd_tanh(y, a);
    case Op::Abs: return bwd_abs(y, a);
    case Op::Min: return bwd_min(y, a, b);
    case Op::Max: return bwd_max(y, a, b);
    case Op::Sign: return bwd_sign(y, a);
    case Op::Const: return !y.is_empty();
    case Op::Var: return true;
  }
  return true;
}

}  // namespace

bool Tape::backward(Interval* v) const {
  for (std::size_t k = code_.size(); k-- > nb_vars_;) {
    const Instr& in = code_[k];
    if (v[k].is_empty()) return false;
    if (in.op == Op::Const) continue;
    Interval a = v[in.a];
    Interval b = op_arity(in.op) == 2 ? v[in.b] : Interval();
    if (!project(in, v[k], a, b)) return false;
    v[in.a] &= a;
    if (op_arity(in.op) == 2) v[in.b] &= b;
    if (v[in.a].is_empty() || (op_arity(in.op) == 2 && v[in.b].is_empty())) return false;
  }
  for (std::size_t k = 0; k < nb_vars_; ++k)
    if (v[k].is_empty()) return false;
  return true;
}

}  // namespace sillage::detail
