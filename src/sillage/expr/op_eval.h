#pragma once
// Forward interval evaluation of one operation: the single switch shared by
// the tape, the batch loops and constant folding.
#include "sillage/expr/expr.h"
#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"

namespace sillage::detail {

// Sign-free integer power with 2 as sqr (tighter and faster).
inline Interval pow_int(const Interval& a, int n) { return n == 2 ? sqr(a) : pow(a, n); }

inline Interval eval_op(Op op, const Interval& a, const Interval& b, int n) {
  switch (op) {
    case Op::Add: return a + b;
    case Op::Sub: return a - b;
    case Op::Mul: return a * b;
    case Op::Div: return a / b;
    case Op::Neg: return -a;
    case Op::Sqr: return sqr(a);
    case Op::Sqrt: return sqrt(a);
    case Op::PowInt: return pow_int(a, n);
    case Op::Pow: return pow(a, b);
    case Op::Root: return root(a, n);
    case Op::Exp: return exp(a);
    case Op::Log: return log(a);
    case Op::Sin: return sin(a);
    case Op::Cos: return cos(a);
    case Op::Tan: return tan(a);
    case Op::Asin: return asin(a);
    case Op::Acos: return acos(a);
    case Op::Atan: return atan(a);
    case Op::Atan2: return atan2(a, b);
    case Op::Sinh: return sinh(a);
    case Op::Cosh: return cosh(a);
    case Op::Tanh: return tanh(a);
    case Op::Abs: return abs(a);
    case Op::Min: return min(a, b);
    case Op::Max: return max(a, b);
    case Op::Sign: return sign(a);
    case Op::Const:
    case Op::Var: break;
  }
  return Interval::all_reals();  // unreachable: leaves are not evaluated here
}

}  // namespace sillage::detail
