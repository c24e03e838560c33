// The AVX2 rows of arith_rows.h: arith_kernels.h's kernels on the
// BranchFreeRounding policy, written again on four lanes. Each step is the
// scalar one's instruction on a wider register (vminpd for minsd, vblendvpd
// for blendvpd, ...), so each lane gives the scalar bits.
#include "sillage/interval/arith_rows.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SILLAGE_AVX2_ROWS 1
#include <immintrin.h>
#else
#define SILLAGE_AVX2_ROWS 0
#endif

#include <type_traits>

#include "sillage/interval/rounding.h"

namespace sillage::detail {

static_assert(sizeof(Interval) == 2 * sizeof(double) && std::is_standard_layout_v<Interval>,
              "Interval must be two contiguous doubles (lb, ub)");

#if SILLAGE_AVX2_ROWS

// Only the functions marked so are compiled for AVX2 (the intrinsics and
// this file's own helpers): no inline function of a shared header is, so
// none can leak AVX2 code into callers on other CPUs.
#define SILLAGE_AVX2 __attribute__((target("avx2,fma")))
#define SILLAGE_AVX2_INLINE __attribute__((target("avx2,fma"), always_inline)) inline

namespace {

using V = __m256d;

// ---- the vocabulary of arith_kernels.h, four lanes wide ----
// The truth value of a comparison, per lane (all ones or all zeros), as Mask.
struct M {
  V m;
};
SILLAGE_AVX2_INLINE V set(double x) { return _mm256_set1_pd(x); }
SILLAGE_AVX2_INLINE M lt(V a, V b) { return {_mm256_cmp_pd(a, b, _CMP_LT_OQ)}; }
SILLAGE_AVX2_INLINE M le(V a, V b) { return {_mm256_cmp_pd(a, b, _CMP_LE_OQ)}; }
SILLAGE_AVX2_INLINE M eq(V a, V b) { return {_mm256_cmp_pd(a, b, _CMP_EQ_OQ)}; }
SILLAGE_AVX2_INLINE M ne(V a, V b) { return {_mm256_cmp_pd(a, b, _CMP_NEQ_OQ)}; }
SILLAGE_AVX2_INLINE M gt(V a, V b) { return lt(b, a); }
SILLAGE_AVX2_INLINE M ge(V a, V b) { return le(b, a); }
SILLAGE_AVX2_INLINE M not_le(V a, V b) { return {_mm256_cmp_pd(a, b, _CMP_NLE_UQ)}; }  // also NaN
SILLAGE_AVX2_INLINE M operator&(M a, M b) { return {_mm256_and_pd(a.m, b.m)}; }
SILLAGE_AVX2_INLINE M operator|(M a, M b) { return {_mm256_or_pd(a.m, b.m)}; }
SILLAGE_AVX2_INLINE M and_not(M a, M b) { return {_mm256_andnot_pd(b.m, a.m)}; }  // a & !b
SILLAGE_AVX2_INLINE V select(M c, V a, V b) { return _mm256_blendv_pd(b, a, c.m); }  // c ? a : b
SILLAGE_AVX2_INLINE V neg(V a) { return _mm256_xor_pd(a, set(-0.0)); }
SILLAGE_AVX2_INLINE V abs(V a) { return _mm256_andnot_pd(set(-0.0), a); }
SILLAGE_AVX2_INLINE V min_nb(V a, V b) { return _mm256_min_pd(a, b); }
SILLAGE_AVX2_INLINE V max_nb(V a, V b) { return _mm256_max_pd(a, b); }
SILLAGE_AVX2_INLINE V fma(V a, V b, V c) { return _mm256_fmadd_pd(a, b, c); }

// step_up / step_down (and next_up_if): the bits of p plus or minus one where m is set.
SILLAGE_AVX2_INLINE V step_up(V p, M m) {
  const __m256i i = _mm256_castpd_si256(p), s = _mm256_castpd_si256(m.m);
  const V away = _mm256_castsi256_pd(_mm256_sub_epi64(i, s)), toward = _mm256_castsi256_pd(_mm256_add_epi64(i, s));
  return _mm256_blendv_pd(away, toward, p);  // below 0, up is toward 0
}
SILLAGE_AVX2_INLINE V step_down(V p, M m) {
  const __m256i i = _mm256_castpd_si256(p), s = _mm256_castpd_si256(m.m);
  const V away = _mm256_castsi256_pd(_mm256_sub_epi64(i, s)), toward = _mm256_castsi256_pd(_mm256_add_epi64(i, s));
  return _mm256_blendv_pd(toward, away, p);
}

// branchless_rounding.h's add_up (2Sum), and the others from it.
SILLAGE_AVX2_INLINE V add_up(V a, V b) {
  const V s = _mm256_add_pd(a, b), bv = _mm256_sub_pd(s, a);
  const V e = _mm256_add_pd(_mm256_sub_pd(a, _mm256_sub_pd(s, bv)), _mm256_sub_pd(b, bv));
  return max_nb(step_up(s, gt(e, set(0.0))), set(-rounding::kMax));
}
SILLAGE_AVX2_INLINE V add_down(V a, V b) { return neg(add_up(neg(a), neg(b))); }
SILLAGE_AVX2_INLINE V sub_up(V a, V b) { return add_up(a, neg(b)); }
SILLAGE_AVX2_INLINE V sub_down(V a, V b) { return neg(add_up(neg(a), b)); }

SILLAGE_AVX2_INLINE V mul_up_nz(V a, V b) {
  const V p = _mm256_mul_pd(a, b);
  return step_up(p, gt(fma(a, b, neg(p)), set(0.0)));
}
SILLAGE_AVX2_INLINE V mul_down_nz(V a, V b) {
  const V p = _mm256_mul_pd(a, b);
  return step_down(p, lt(fma(a, b, neg(p)), set(0.0)));
}
SILLAGE_AVX2_INLINE V div_up(V a, V b) {
  const V q = _mm256_div_pd(a, b), r = fma(neg(q), b, a), z = set(0.0);
  return step_up(q, (gt(r, z) & gt(b, z)) | (lt(r, z) & lt(b, z)));
}
SILLAGE_AVX2_INLINE V div_down(V a, V b) {
  const V q = _mm256_div_pd(a, b), r = fma(neg(q), b, a), z = set(0.0);
  return step_down(q, (lt(r, z) & gt(b, z)) | (gt(r, z) & lt(b, z)));
}
SILLAGE_AVX2_INLINE V sqrt_up(V a) {
  const V s = _mm256_sqrt_pd(a);
  return step_up(s, gt(fma(neg(s), s, a), set(0.0)));
}
SILLAGE_AVX2_INLINE V sqrt_down(V a) {
  const V s = _mm256_sqrt_pd(a);
  return step_down(s, lt(fma(neg(s), s, a), set(0.0)));
}

SILLAGE_AVX2_INLINE M mul_rare(V a, V b) {
  return lt(abs(_mm256_mul_pd(a, b)), set(0x1p-968)) & ne(a, set(0.0)) & ne(b, set(0.0));
}
SILLAGE_AVX2_INLINE M div_rare(V a, V b) {
  const V fa = abs(a), fb = abs(b), fq = abs(_mm256_div_pd(a, b));
  const V z = set(0.0), inf = set(rounding::kInf), tiny = set(0x1p-968), huge = set(0x1p1000);
  const M finite_nonzero = gt(fa, z) & lt(fa, inf) & gt(fb, z) & lt(fb, inf);
  const M safe = ge(fa, tiny) & ge(fb, tiny) & le(fb, huge) & ge(fq, tiny) & le(fq, huge);
  return and_not(finite_nonzero, safe);
}
SILLAGE_AVX2_INLINE M sqrt_rare(V a) { return gt(a, set(0.0)) & lt(a, set(0x1p-968)); }

SILLAGE_AVX2_INLINE M no_set(V lo, V hi) { return not_le(lo, hi); }
SILLAGE_AVX2_INLINE V corner(V p) { return _mm256_and_pd(_mm256_cmp_pd(p, p, _CMP_ORD_Q), p); }

// Four intervals as their lower and upper bounds, lanes in the order 0 2 1 3
// (unpacklo / unpackhi within 128-bit halves: no shuffle across them).
struct Quad {
  V lo, hi;
};
SILLAGE_AVX2_INLINE Quad load(const Interval* p) {
  const auto* d = reinterpret_cast<const double*>(p);
  const V v0 = _mm256_loadu_pd(d), v1 = _mm256_loadu_pd(d + 4);
  return {_mm256_unpacklo_pd(v0, v1), _mm256_unpackhi_pd(v0, v1)};
}
SILLAGE_AVX2_INLINE void store(Interval* p, Quad q) {
  auto* d = reinterpret_cast<double*>(p);
  _mm256_storeu_pd(d, _mm256_unpacklo_pd(q.lo, q.hi));
  _mm256_storeu_pd(d + 4, _mm256_unpackhi_pd(q.lo, q.hi));
}

// bounds_or_empty: + 0.0 turns a -0 bound into +0.
SILLAGE_AVX2_INLINE Quad bounds_or_empty(M empty, V lo, V hi) {
  const V z = set(0.0);
  return {select(empty, set(rounding::kInf), _mm256_add_pd(lo, z)),
          select(empty, set(-rounding::kInf), _mm256_add_pd(hi, z))};
}

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

bool avx2_rows() {
  static const bool on = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return on;
}

void arith_rows_avx2(RowOp op, Interval* r, RowArg a, RowArg b, std::size_t count) {
  const Operand x{a.p, a.constant}, y{b.p ? b.p : a.p, b.p ? b.constant : a.constant};
  switch (op) {
    case RowOp::Add: return rows<Add>(r, x, y, count);
    case RowOp::Sub: return rows<Sub>(r, x, y, count);
    case RowOp::Mul: return rows<Mul>(r, x, y, count);
    case RowOp::Div: return rows<Div>(r, x, y, count);
    case RowOp::Sqr: return rows<Sqr>(r, x, y, count);
    case RowOp::Sqrt: return rows<Sqrt>(r, x, y, count);
  }
}

#else

bool avx2_rows() { return false; }
void arith_rows_avx2(RowOp, Interval*, RowArg, RowArg, std::size_t) {}

#endif

}  // namespace sillage::detail
