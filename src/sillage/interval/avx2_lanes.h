#pragma once
// The vocabulary of arith_kernels.h and branchless_rounding.h four lanes wide,
// with AVX2 and FMA (internal header of the files compiled for AVX2 in their
// own functions: arith_rows_avx2.cpp, dynamics/slice_rule_x4.cpp). Each
// step is the scalar one's instruction on a wider register (vminpd for
// minsd, vblendvpd for blendvpd, ...), so each lane gives the scalar bits.
//
// Only the functions marked SILLAGE_AVX2 are compiled for AVX2, and all of
// them here are always inlined into such functions: no inline function of a
// shared header is, so none can leak AVX2 code into callers on other CPUs.
// Its declarations exist only where SILLAGE_AVX2_LANES is 1.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SILLAGE_AVX2_LANES 1
#include <immintrin.h>
#else
#define SILLAGE_AVX2_LANES 0
#endif

#include <type_traits>

#include "sillage/interval/interval.h"
#include "sillage/interval/rounding.h"

#if SILLAGE_AVX2_LANES

#define SILLAGE_AVX2 __attribute__((target("avx2,fma")))
#define SILLAGE_AVX2_INLINE __attribute__((target("avx2,fma"), always_inline)) inline

namespace sillage::detail {

static_assert(sizeof(Interval) == 2 * sizeof(double) && std::is_standard_layout_v<Interval>,
              "Interval must be two contiguous doubles (lb, ub)");

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
  const M bv_overflowed = lt(bv, set(-rounding::kMax)) & ge(s, set(-rounding::kMax));  // as the scalar add_up
  return max_nb(step_up(s, gt(e, set(0.0)) | bv_overflowed), set(-rounding::kMax));
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

}  // namespace sillage::detail

#endif  // SILLAGE_AVX2_LANES
