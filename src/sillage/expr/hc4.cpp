// HC4-revise backward pass (thesis 2.3.1): from the output down to the
// variables, each node projects its (contracted) value onto its operands with
// the backward functions of backward.h. Operands are contracted on copies then
// intersected, so a node shared by several users (or used twice by one, as
// in x * x) receives the intersection of all its projections.
//
// A node whose value is still its forward image [f](a, b) has nothing to
// project when f is defined on the whole of a and b: every point of a finds
// a partner in b with an image in [f](a, b) (operands shrunk since by other
// users included), so the projections keep a and b whole. Such nodes are
// skipped; near a fixed point they are most of the DAG.
#include <cstdint>
#include <vector>

#include "sillage/expr/batch_kernels.h"
#include "sillage/expr/tape.h"
#include "sillage/interval/arith_rows.h"
#include "sillage/interval/backward.h"
#include "sillage/interval/backward_detail.h"

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

// When a slot still at its forward value [f](a, b) may skip its projection:
// where f is defined on the whole of a and b (see the header comment).
enum class Idle : std::uint8_t { Skip, IfDivisorSigned, IfNonNegative, IfPositive, IfSigned, Project };

Idle idle_rule(const Instr& in) {
  switch (in.op) {
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Neg:
    case Op::Sqr:
    case Op::Exp:
    case Op::Sin:
    case Op::Cos:
    case Op::Atan:
    case Op::Sinh:
    case Op::Cosh:
    case Op::Tanh:
    case Op::Abs:
    case Op::Min:
    case Op::Max:
    case Op::Sign: return Idle::Skip;
    case Op::Div: return Idle::IfDivisorSigned;
    case Op::Sqrt: return Idle::IfNonNegative;
    case Op::Log: return Idle::IfPositive;
    case Op::PowInt: return in.n >= 0 ? Idle::Skip : Idle::IfSigned;
    default: return Idle::Project;  // the others may cut their operands even so
  }
}

bool strictly_signed(const Interval& x) { return x.lb() > 0 || x.ub() < 0; }

bool keeps_operands(Idle rule, const Interval& a, const Interval& b) {
  switch (rule) {
    case Idle::Skip: return true;
    case Idle::IfDivisorSigned: return strictly_signed(b);
    case Idle::IfNonNegative: return a.lb() >= 0;
    case Idle::IfPositive: return a.lb() > 0;
    case Idle::IfSigned: return strictly_signed(a);
    case Idle::Project: return false;
  }
  return false;
}

// x &= p; records whether x changed.
void meet(Interval& x, const Interval& p, std::uint8_t& moved) {
  const Interval m = x & p;
  if (m != x) {
    x = m;
    moved = 1;
  }
}

// Projects slot k (rows r, operands ra, rb) onto its operands for the boxes
// j < count still to be contracted; `proj` is the projection of the slot's
// operation, chosen once per row so that the box loop holds no dispatch.
template <bool kBinary, class Proj>
void backward_row(std::size_t count, Idle rule, Interval* r, Interval* ra, Interval* rb, const std::uint8_t* m,
                  std::uint8_t* ma, std::uint8_t* mb, std::uint8_t* ok, Proj proj) {
  for (std::size_t j = 0; j < count; ++j) {
    if (!ok[j]) continue;
    if (r[j].is_empty()) {
      ok[j] = 0;
      continue;
    }
    if (!m[j] && keeps_operands(rule, ra[j], kBinary ? rb[j] : ra[j])) continue;
    Interval a = ra[j];
    Interval b = kBinary ? rb[j] : Interval();
    if (!proj(r[j], a, b)) {
      ok[j] = 0;
      continue;
    }
    meet(ra[j], a, ma[j]);
    if (kBinary) meet(rb[j], b, mb[j]);
    if (ra[j].is_empty() || (kBinary && rb[j].is_empty())) ok[j] = 0;
  }
}

// bwd_add and bwd_sub of backward_arith.cpp with the operations Ops
// (batch_kernels.h): the same results, the rounding kernels inlined.
template <class Ops>
bool bwd_add_with(const Interval& y_in, Interval& x1, Interval& x2) {
  const Interval y = y_in;
  x1 &= Ops::sub(y, x2);
  x2 &= Ops::sub(y, x1);
  return settle(x1, x2);
}

template <class Ops>
bool bwd_sub_with(const Interval& y_in, Interval& x1, Interval& x2) {
  const Interval y = y_in;
  x1 &= Ops::add(y, x2);
  x2 &= Ops::sub(x1, y);
  return settle(x1, x2);
}

// backward_row of bwd_add_with (kSub false) or bwd_sub_with on the AVX2 rows
// (arith_rows.h, the same bits): their two interval operations computed over
// the whole row first (four boxes at a time; wasted on the boxes that skip),
// then applied to the boxes the loop of backward_row would project.
template <bool kSub>
void add_sub_row_avx2(std::size_t count, Idle rule, Interval* r, Interval* ra, Interval* rb, const std::uint8_t* m,
                      std::uint8_t* ma, std::uint8_t* mb, std::uint8_t* ok) {
  thread_local std::vector<Interval> tmp;
  tmp.resize(2 * count);
  Interval *const x1 = tmp.data(), *const p2 = tmp.data() + count;
  // y = a + b: a &= y - b, b &= y - a; y = a - b: a &= y + b, b &= a - y.
  arith_rows_avx2(kSub ? RowOp::Add : RowOp::Sub, x1, RowArg{r}, RowArg{rb}, count);
  for (std::size_t j = 0; j < count; ++j) x1[j] = ra[j] & x1[j];
  arith_rows_avx2(RowOp::Sub, p2, RowArg{kSub ? x1 : r}, RowArg{kSub ? r : x1}, count);
  for (std::size_t j = 0; j < count; ++j) {
    if (!ok[j]) continue;
    if (r[j].is_empty()) {
      ok[j] = 0;
      continue;
    }
    if (!m[j] && keeps_operands(rule, ra[j], rb[j])) continue;
    const Interval a = x1[j], b = rb[j] & p2[j];
    if (a.is_empty() || b.is_empty()) {  // settle()
      ok[j] = 0;
      continue;
    }
    meet(ra[j], a, ma[j]);
    meet(rb[j], b, mb[j]);
    if (ra[j].is_empty() || rb[j].is_empty()) ok[j] = 0;
  }
}

// The backward pass over `count` boxes (see Tape::backward_batch); kOne: a
// single box, for which the compiler drops the inner loops, and which keeps
// the projections of backward.h (the reference of the batch). Ops: the
// interval operations of the batch's + and − rows.
template <bool kOne, class Ops = ScalarOps>
void backward_rows(const Tape& t, Interval* rows, std::size_t count_in, const Interval* y, std::uint8_t* ok,
                   bool skip_idle) {
  const std::size_t count = kOne ? 1 : count_in;
  const std::vector<Instr>& code = t.code();
  // moved[k * count + j]: slot k of box j differs from its forward value. Per thread, like the rows.
  thread_local std::vector<std::uint8_t> flags;
  flags.assign(code.size() * count, 0);
  const auto row = [&](std::size_t k) { return rows + k * count; };
  const auto moved = [&](std::size_t k) { return flags.data() + k * count; };
  for (std::size_t i = 0; i < t.outputs().size(); ++i) {
    Interval* const o = row(t.outputs()[i]);
    std::uint8_t* const m = moved(t.outputs()[i]);
    for (std::size_t j = 0; j < count; ++j) {
      if (!ok[j]) continue;
      meet(o[j], y[i], m[j]);
      if (o[j].is_empty()) ok[j] = 0;
    }
  }
  using I = const Interval&;
  for (std::size_t k = code.size(); k-- > t.nb_vars();) {
    const Instr& in = code[k];
    const Idle rule = skip_idle ? idle_rule(in) : Idle::Project;
    Interval *const r = row(k), *const ra = row(in.a), *const rb = row(in.b);
    std::uint8_t *const m = moved(k), *const ma = moved(in.a), *const mb = moved(in.b);
    const auto binary = [&](auto proj) { backward_row<true>(count, rule, r, ra, rb, m, ma, mb, ok, proj); };
    const auto unary = [&](auto proj) { backward_row<false>(count, rule, r, ra, rb, m, ma, mb, ok, proj); };
    switch (in.op) {  // the frequent operations get a loop of their own
      case Op::Const:  // nothing to project: an emptied constant empties its box
        for (std::size_t j = 0; j < count; ++j)
          if (r[j].is_empty()) ok[j] = 0;
        break;
      // The AVX2 add/sub rows on the portable path only: on the AVX-512 path they
      // did not beat the embedded rounding (the pointwise contractor at 57-60 ns per slice either way).
      case Op::Add:
        if constexpr (kOne) binary([](I v, Interval& a, Interval& b) { return bwd_add(v, a, b); });
        else if (Ops::kPortable && avx2_rows_for(count)) add_sub_row_avx2<false>(count, rule, r, ra, rb, m, ma, mb, ok);
        else binary([](I v, Interval& a, Interval& b) { return bwd_add_with<Ops>(v, a, b); });
        break;
      case Op::Sub:
        if constexpr (kOne) binary([](I v, Interval& a, Interval& b) { return bwd_sub(v, a, b); });
        else if (Ops::kPortable && avx2_rows_for(count)) add_sub_row_avx2<true>(count, rule, r, ra, rb, m, ma, mb, ok);
        else binary([](I v, Interval& a, Interval& b) { return bwd_sub_with<Ops>(v, a, b); });
        break;
      case Op::Mul: binary([](I v, Interval& a, Interval& b) { return bwd_mul(v, a, b); }); break;
      case Op::Div: binary([](I v, Interval& a, Interval& b) { return bwd_div(v, a, b); }); break;
      case Op::Sqr: unary([](I v, Interval& a, Interval&) { return bwd_sqr(v, a); }); break;
      case Op::Sqrt: unary([](I v, Interval& a, Interval&) { return bwd_sqrt(v, a); }); break;
      case Op::Sin: unary([](I v, Interval& a, Interval&) { return bwd_sin(v, a); }); break;
      case Op::Cos: unary([](I v, Interval& a, Interval&) { return bwd_cos(v, a); }); break;
      default:
        if (op_arity(in.op) == 2) {
          binary([&in](I v, Interval& a, Interval& b) { return project(in, v, a, b); });
        } else {
          unary([&in](I v, Interval& a, Interval& b) { return project(in, v, a, b); });
        }
    }
  }
  for (std::size_t k = 0; k < t.nb_vars(); ++k)
    for (std::size_t j = 0; j < count; ++j)
      if (row(k)[j].is_empty()) ok[j] = 0;
}

}  // namespace

bool Tape::backward(Interval* v, const Interval* y, bool skip_idle) const {
  std::uint8_t ok = 1;
  backward_rows<true>(*this, v, 1, y, &ok, skip_idle);
  return ok != 0;
}

void Tape::backward_batch(Interval* rows, std::size_t count, const Interval* y, std::uint8_t* ok,
                          bool skip_idle) const {
  with_rounded_ops([&](auto ops) { backward_rows<false, decltype(ops)>(*this, rows, count, y, ok, skip_idle); });
}

}  // namespace sillage::detail
