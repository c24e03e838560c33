#pragma once
// Primitive contractors of binary constraints y = f(x), on the box (y, x): the
// result first, as the thesis' C_exp (2.32):
//   [y] ∩= f([x]), then [x] contracted by the backward projection bwd_f.
// f is any elementary function; pow and root take an integer n.
#include <string>

#include "sillage/ctc/ctc.h"

namespace sillage {

enum class UnaryOp { neg, sqr, sqrt, exp, log, sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, abs, sign, pow, root };

class CtcUnary : public Ctc {
 public:
  // n is the integer of pow (y = x^n) and root (y = root(x, n)); ignored otherwise.
  explicit CtcUnary(UnaryOp op, int n = 0);
  // By name: "neg", "sqr", "sqrt", "exp", "log", "sin", ..., "pow", "root" (else Error).
  explicit CtcUnary(const std::string& op, int n = 0);
  void contract(IntervalVector& x) const override;
  std::string name() const override;
  UnaryOp op() const { return op_; }

 private:
  UnaryOp op_;
  int n_;
};

}  // namespace sillage
