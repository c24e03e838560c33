#pragma once
// Primitive contractors of ternary constraints z = x op y, on the box (z, x, y):
// the result first, as the thesis' C+ (2.31):
//   [z] ∩= [x] op [y], then [x], [y] contracted by the backward projection bwd_op.
// CtcAdd()([4,5], [0,3], [-2,2]) = ([4,5], [2,3], [1,2]).
// For atan2 the box is (theta, y, x) with theta = atan2(y, x); for pow it is
// (z, x, p) with z = x^p (real exponent).
#include <string>

#include "sillage/ctc/ctc.h"

namespace sillage {

enum class BinaryOp { add, sub, mul, div, min, max, atan2, pow };

class CtcBinary : public Ctc {
 public:
  explicit CtcBinary(BinaryOp op) : Ctc(3), op_(op) {}
  // By name: "add", "sub", "mul", "div", "min", "max", "atan2", "pow" (else Error).
  explicit CtcBinary(const std::string& op);
  void contract(IntervalVector& x) const override;
  std::string name() const override;
  BinaryOp op() const { return op_; }

 private:
  BinaryOp op_;
};

// The usual ones under their own names.

// The contractor of z = x + y on (z, x, y) (2.31): CtcAdd() on ([4,5], [0,3], [-2,2]) gives
// ([4,5], [2,3], [1,2]).
class CtcAdd : public CtcBinary {
 public:
  // The contractor of z = x + y.
  CtcAdd() : CtcBinary(BinaryOp::add) {}
};
// The contractor of z = x - y on (z, x, y).
class CtcSub : public CtcBinary {
 public:
  // The contractor of z = x - y.
  CtcSub() : CtcBinary(BinaryOp::sub) {}
};
// The contractor of z = x * y on (z, x, y).
class CtcMul : public CtcBinary {
 public:
  // The contractor of z = x * y.
  CtcMul() : CtcBinary(BinaryOp::mul) {}
};
// The contractor of z = x / y on (z, x, y).
class CtcDiv : public CtcBinary {
 public:
  // The contractor of z = x / y.
  CtcDiv() : CtcBinary(BinaryOp::div) {}
};

}  // namespace sillage
