#include "sillage/ctc/ctc_unary.h"

#include <array>
#include <utility>

#include "sillage/interval/backward.h"
#include "sillage/interval/elementary.h"

namespace sillage {

namespace {

constexpr std::array<std::pair<UnaryOp, const char*>, 18> kNames{{
    {UnaryOp::neg, "neg"},   {UnaryOp::sqr, "sqr"},   {UnaryOp::sqrt, "sqrt"}, {UnaryOp::exp, "exp"},
    {UnaryOp::log, "log"},   {UnaryOp::sin, "sin"},   {UnaryOp::cos, "cos"},   {UnaryOp::tan, "tan"},
    {UnaryOp::asin, "asin"}, {UnaryOp::acos, "acos"}, {UnaryOp::atan, "atan"}, {UnaryOp::sinh, "sinh"},
    {UnaryOp::cosh, "cosh"}, {UnaryOp::tanh, "tanh"}, {UnaryOp::abs, "abs"},   {UnaryOp::sign, "sign"},
    {UnaryOp::pow, "pow"},   {UnaryOp::root, "root"},
}};

UnaryOp parse_op(const std::string& s) {
  for (const auto& [op, n] : kNames) {
    if (s == n) return op;
  }
  throw Error("CtcUnary: unknown function '" + s + "'");
}

Interval forward(UnaryOp op, int n, const Interval& x) {
  switch (op) {
    case UnaryOp::neg: return -x;
    case UnaryOp::sqr: return sqr(x);
    case UnaryOp::sqrt: return sqrt(x);
    case UnaryOp::exp: return exp(x);
    case UnaryOp::log: return log(x);
    case UnaryOp::sin: return sin(x);
    case UnaryOp::cos: return cos(x);
    case UnaryOp::tan: return tan(x);
    case UnaryOp::asin: return asin(x);
    case UnaryOp::acos: return acos(x);
    case UnaryOp::atan: return atan(x);
    case UnaryOp::sinh: return sinh(x);
    case UnaryOp::cosh: return cosh(x);
    case UnaryOp::tanh: return tanh(x);
    case UnaryOp::abs: return abs(x);
    case UnaryOp::sign: return sign(x);
    case UnaryOp::pow: return pow(x, n);
    case UnaryOp::root: return root(x, n);
  }
  return Interval();  // unreachable; the whole line keeps the contractor safe
}

bool backward(UnaryOp op, int n, const Interval& y, Interval& x) {
  switch (op) {
    case UnaryOp::neg: return bwd_neg(y, x);
    case UnaryOp::sqr: return bwd_sqr(y, x);
    case UnaryOp::sqrt: return bwd_sqrt(y, x);
    case UnaryOp::exp: return bwd_exp(y, x);
    case UnaryOp::log: return bwd_log(y, x);
    case UnaryOp::sin: return bwd_sin(y, x);
    case UnaryOp::cos: return bwd_cos(y, x);
    case UnaryOp::tan: return bwd_tan(y, x);
    case UnaryOp::asin: return bwd_asin(y, x);
    case UnaryOp::acos: return bwd_acos(y, x);
    case UnaryOp::atan: return bwd_atan(y, x);
    case UnaryOp::sinh: return bwd_sinh(y, x);
    case UnaryOp::cosh: return bwd_cosh(y, x);
    case UnaryOp::tanh: return bwd_tanh(y, x);
    case UnaryOp::abs: return bwd_abs(y, x);
    case UnaryOp::sign: return bwd_sign(y, x);
    case UnaryOp::pow: return bwd_pow(y, x, n);
    case UnaryOp::root: return bwd_root(y, x, n);
  }
  return true;
}

}  // namespace

CtcUnary::CtcUnary(UnaryOp op, int n) : Ctc(2), op_(op), n_(n) {
  if (op == UnaryOp::root && n <= 0) {
    throw Error("CtcUnary(root): the root order n must be positive, got " + std::to_string(n));
  }
}

CtcUnary::CtcUnary(const std::string& op, int n) : CtcUnary(parse_op(op), n) {}

std::string CtcUnary::name() const {
  for (const auto& [op, s] : kNames) {
    if (op != op_) continue;
    if (op == UnaryOp::pow || op == UnaryOp::root) return std::string("CtcUnary(") + s + ", " + std::to_string(n_) + ")";
    return std::string("CtcUnary(") + s + ")";
  }
  return "CtcUnary";
}

void CtcUnary::contract(IntervalVector& x) const {
  check_dim(x);
  if (x.is_empty()) return x.set_empty();
  x[0] &= forward(op_, n_, x[1]);
  if (x[0].is_empty() || !backward(op_, n_, x[0], x[1]) || x.is_empty()) x.set_empty();
}

}  // namespace sillage
