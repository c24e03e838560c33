// The AVX2 rows of arith_rows.h: arith_kernels.h's kernels on the
// BranchFreeRounding policy, written again on four lanes with the
// vocabulary of avx2_lanes.h, so each lane gives the scalar bits.
#include "sillage/interval/arith_rows.h"

#include <cmath>

#include "sillage/interval/avx2_lanes.h"

namespace sillage::detail {

#if SILLAGE_AVX2_LANES

namespace {

// ---- the kernels: x = [a, b], y = [c, d]; `rare` receives the lanes to redo ----
struct Add {
  SILLAGE_AVX2_INLINE static Quad apply(Quad x, Quad y, M&) {
    return bounds_or_empty(no_set(x.lo, x.hi) | no_set(y.lo, y.hi), add_down(x.lo, y.lo), add_up(x.hi, y.hi));
  }
  static Interval scalar(const Interval& x, const Interval& y) { return x + y; }
};

struct Sub {
  SILLAGE_AVX2_INLINE static Quad apply(Quad x, Quad y, M&) {
    return bounds_or_empty(no_set(x.lo, x.hi) | no_set(y.lo, y.hi), sub_down(x.lo, y.hi), sub_up(x.hi, y.lo));
  }
  static Interval scalar(const Interval& x, const Interval& y) { return x - y; }
};

struct Mul {
  SILLAGE_AVX2_INLINE static Quad apply(Quad x, Quad y, M& rare) {
    const V a = x.lo, b = x.hi, c = y.lo, d = y.hi, z = set(0.0);
    const M a_nn = ge(a, z), b_nn = ge(b, z);
    const V a_lo = select(a_nn, c, d), a_hi = select(a_nn, d, c);
    const V b_lo = select(b_nn, c, d), b_hi = select(b_nn, d, c);
    rare = mul_rare(a, a_lo) | mul_rare(a, a_hi) | mul_rare(b, b_lo) | mul_rare(b, b_hi);
    const V lo = min_nb(corner(mul_down_nz(a, a_lo)), corner(mul_down_nz(b, b_lo)));
    const V hi = max_nb(corner(mul_up_nz(a, a_hi)), corner(mul_up_nz(b, b_hi)));
    return bounds_or_empty(no_set(a, b) | no_set(c, d), lo, hi);
  }
  static Interval scalar(const Interval& x, const Interval& y) { return x * y; }
};

struct Div {
  SILLAGE_AVX2_INLINE static Quad apply(Quad x, Quad y, M& rare) {
    const V z = set(0.0), inf = set(rounding::kInf);
    const V a = x.lo, b = x.hi, c = _mm256_add_pd(y.lo, z), d = y.hi;  // c: the limit from above 0, +0
    const V dn = select(eq(d, z), set(-0.0), d);                         // the limit from below 0, -0
    const M pos = ge(c, z), a_nn = ge(a, z), b_pos = gt(b, z);
    const V lo_num = select(pos, a, b), hi_num = select(pos, b, a);
    const V lo_den = select(pos, select(a_nn, d, c), select(b_pos, dn, c));
    const V hi_den = select(pos, select(b_pos, c, d), select(a_nn, c, dn));
    rare = div_rare(lo_num, lo_den) | div_rare(hi_num, hi_den);
    V lo = div_down(lo_num, lo_den), hi = div_up(hi_num, hi_den);
    const M straddles = lt(c, z) & gt(d, z), x_zero = eq(a, z) & eq(b, z);
    lo = select(straddles, select(x_zero, z, neg(inf)), lo);
    hi = select(straddles, select(x_zero, z, inf), hi);
    return bounds_or_empty(no_set(a, b) | no_set(c, d) | (eq(c, z) & eq(d, z)), lo, hi);
  }
  static Interval scalar(const Interval& x, const Interval& y) { return x / y; }
};

// x · y and x / y for a constant y = [c, d] of one sign, finite, without 0
// (a point among them): Mul's and Div's kernels with the sign choices of y
// made, so the same bits (the two products or quotients they would keep) at
// half the work. kNeg: y < 0, the bounds of x swap; then each bound of x
// meets the bound of y its own sign selects, the other one for ÷.
struct MulConstant {
  static constexpr bool kInverse = false;
  SILLAGE_AVX2_INLINE static V down(V a, V c) { return mul_down_nz(a, c); }  // c finite, nonzero: no 0·inf
  SILLAGE_AVX2_INLINE static V up(V a, V c) { return mul_up_nz(a, c); }
  SILLAGE_AVX2_INLINE static M rare(V a, V c) { return mul_rare(a, c); }
  static Interval scalar(const Interval& x, const Interval& y) { return x * y; }
};

struct DivConstant {
  static constexpr bool kInverse = true;
  SILLAGE_AVX2_INLINE static V down(V a, V c) { return div_down(a, c); }
  SILLAGE_AVX2_INLINE static V up(V a, V c) { return div_up(a, c); }
  SILLAGE_AVX2_INLINE static M rare(V a, V c) { return div_rare(a, c); }
  static Interval scalar(const Interval& x, const Interval& y) { return x / y; }
};

template <class Op, bool kNeg, bool kPoint>
struct ByConstant {
  SILLAGE_AVX2_INLINE static Quad apply(Quad x, Quad y, M& rare) {
    const V lo = kNeg ? x.hi : x.lo, hi = kNeg ? x.lo : x.hi, z = set(0.0);
    // For ×, a bound of x ≥ 0 takes c for the lower bound and d for the upper one; ÷ the
    // reverse; a point has nothing to choose.
    const V small = Op::kInverse ? y.hi : y.lo, large = Op::kInverse ? y.lo : y.hi;
    const V c_lo = kPoint ? small : select(ge(lo, z), small, large);
    const V c_hi = kPoint ? small : select(ge(hi, z), large, small);
    rare = Op::rare(lo, c_lo) | Op::rare(hi, c_hi);
    return bounds_or_empty(no_set(x.lo, x.hi), Op::down(lo, c_lo), Op::up(hi, c_hi));
  }
  static Interval scalar(const Interval& x, const Interval& y) { return Op::scalar(x, y); }
};

struct Sqr {
  SILLAGE_AVX2_INLINE static Quad apply(Quad x, Quad, M& rare) {
    const V a = x.lo, b = x.hi;
    const V mig = max_nb(max_nb(a, neg(b)), set(0.0)), mag = max_nb(neg(a), b);
    rare = mul_rare(mig, mig) | mul_rare(mag, mag);
    return bounds_or_empty(no_set(a, b), mul_down_nz(mig, mig), mul_up_nz(mag, mag));
  }
  static Interval scalar(const Interval& x, const Interval&) { return sqr(x); }
};

struct Sqrt {
  SILLAGE_AVX2_INLINE static Quad apply(Quad x, Quad, M& rare) {
    const V a = x.lo, b = x.hi, a0 = max_nb(a, set(0.0));
    rare = sqrt_rare(a0) | sqrt_rare(b);
    return bounds_or_empty(no_set(a, b) | lt(b, set(0.0)), sqrt_down(a0), sqrt_up(b));
  }
  static Interval scalar(const Interval& x, const Interval&) { return sqrt(x); }
};

// An operand: a row read four at a time, or one interval broadcast.
struct Operand {
  const Interval* p;
  bool constant;
  SILLAGE_AVX2_INLINE Quad quad(std::size_t i) const {
    return constant ? Quad{set(p->lb()), set(p->ub())} : load(p + i);
  }
  const Interval& at(std::size_t i) const { return constant ? *p : p[i]; }
};

// out[i .. i + 3] with kernel K; the rare lanes' blocks by Interval's operators.
template <class K>
SILLAGE_AVX2_INLINE void block(Interval* out, Operand x, Operand y, std::size_t i) {
  M rare{set(0.0)};
  const Quad q = K::apply(x.quad(i), y.quad(i), rare);
  if (_mm256_movemask_pd(rare.m) == 0) [[likely]] {
    store(out + i, q);
  } else {
    for (std::size_t j = i; j < i + 4; ++j) out[j] = K::scalar(x.at(j), y.at(j));
  }
}

// Rows i < count with kernel K; a tail below four by Interval's operators.
template <class K>
SILLAGE_AVX2 void rows(Interval* r, Operand a, Operand b, std::size_t count) {
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) block<K>(r, a, b, i);
  for (; i < count; ++i) r[i] = K::scalar(a.at(i), b.at(i));
}

}  // namespace

bool avx2_rows_available() {
  static const bool available = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return available;
}

namespace {
bool& avx2_rows_on() {
  static bool on = avx2_rows_available();
  return on;
}
}  // namespace

bool avx2_rows() { return avx2_rows_on(); }
void set_avx2_rows(bool on) { avx2_rows_on() = on && avx2_rows_available(); }

namespace {

// A constant of one sign, finite, without 0 (ByConstant's operand).
bool one_sign(const Operand& o) {
  const double c = o.p->lb(), d = o.p->ub();
  return o.constant && c <= d && ((c > 0 && d <= rounding::kMax) || (d < 0 && c >= -rounding::kMax));  // not empty
}

// Rows x op y by ByConstant, y a constant of one sign.
template <class Op>
void by_constant(Interval* r, Operand x, Operand y, std::size_t count) {
  const bool neg = y.p->ub() < 0, point = y.p->lb() == y.p->ub();
  if (point) return neg ? rows<ByConstant<Op, true, true>>(r, x, y, count) : rows<ByConstant<Op, false, true>>(r, x, y, count);
  neg ? rows<ByConstant<Op, true, false>>(r, x, y, count) : rows<ByConstant<Op, false, false>>(r, x, y, count);
}

}  // namespace

void arith_rows_avx2(RowOp op, Interval* r, RowArg a, RowArg b, std::size_t count) {
  const Operand x{a.p, a.constant}, y{b.p ? b.p : a.p, b.p ? b.constant : a.constant};
  switch (op) {
    case RowOp::Add: return rows<Add>(r, x, y, count);
    case RowOp::Sub: return rows<Sub>(r, x, y, count);
    case RowOp::Mul:
      if (one_sign(y)) return by_constant<MulConstant>(r, x, y, count);
      if (one_sign(x)) return by_constant<MulConstant>(r, y, x, count);  // c·x = x·c, the optimal bounds either way
      return rows<Mul>(r, x, y, count);
    case RowOp::Div:
      if (one_sign(y)) return by_constant<DivConstant>(r, x, y, count);
      return rows<Div>(r, x, y, count);
    case RowOp::Sqr: return rows<Sqr>(r, x, y, count);
    case RowOp::Sqrt: return rows<Sqrt>(r, x, y, count);
  }
}

#else

bool avx2_rows() { return false; }
bool avx2_rows_available() { return false; }
void set_avx2_rows(bool) {}
void arith_rows_avx2(RowOp, Interval*, RowArg, RowArg, std::size_t) {}

#endif

}  // namespace sillage::detail
