#include "sillage/ctc/ctc_binary.h"

#include <array>
#include <utility>

#include "sillage/interval/backward.h"
#include "sillage/interval/elementary.h"

namespace sillage {

namespace {

constexpr std::array<std::pair<BinaryOp, const char*>, 8> kNames{{{BinaryOp::add, "add"},
                                                                  {BinaryOp::sub, "sub"},
                                                                  {BinaryOp::mul, "mul"},
                                                                  {BinaryOp::div, "div"},
                                                                  {BinaryOp::min, "min"},
                                                                  {BinaryOp::max, "max"},
                                                                  {BinaryOp::atan2, "atan2"},
                                                                  {BinaryOp::pow, "pow"}}};

BinaryOp parse_op(const std::string& s) {
  for (const auto& [op, n] : kNames) {
    if (s == n) return op;
  }
  throw Error("CtcBinary: unknown operation '" + s + "' (expected add, sub, mul, div, min, max, atan2 or pow)");
}

Interval forward(BinaryOp op, const Interval& x, const Interval& y) {
  switch (op) {
    case BinaryOp::add: return x + y;
    case BinaryOp::sub: return x - y;
    case BinaryOp::mul: return x * y;
    case BinaryOp::div: return x / y;
    case BinaryOp::min: return min(x, y);
    case BinaryOp::max: return max(x, y);
    case BinaryOp::atan2: return atan2(x, y);
    case BinaryOp::pow: return pow(x, y);
  }
  return Interval();  // unreachable; the whole line keeps the contractor safe
}

bool backward(BinaryOp op, const Interval& z, Interval& x, Interval& y) {
  switch (op) {
    case BinaryOp::add: return bwd_add(z, x, y);
    case BinaryOp::sub: return bwd_sub(z, x, y);
    case BinaryOp::mul: return bwd_mul(z, x, y);
    case BinaryOp::div: return bwd_div(z, x, y);
    case BinaryOp::min: return bwd_min(z, x, y);
    case BinaryOp::max: return bwd_max(z, x, y);
    case BinaryOp::atan2: return bwd_atan2(z, x, y);
    case BinaryOp::pow: return bwd_pow(z, x, y);
  }
  return true;
}

}  // namespace

CtcBinary::CtcBinary(const std::string& op) : CtcBinary(parse_op(op)) {}

std::string CtcBinary::name() const {
  for (const auto& [op, n] : kNames) {
    if (op == op_) return std::string("CtcBinary(") + n + ")";
  }
  return "CtcBinary";
}

void CtcBinary::contract(IntervalVector& x) const {
  check_dim(x);
  if (x.is_empty()) return x.set_empty();
  x[0] &= forward(op_, x[1], x[2]);
  if (x[0].is_empty() || !backward(op_, x[0], x[1], x[2]) || x.is_empty()) x.set_empty();
}

}  // namespace sillage
