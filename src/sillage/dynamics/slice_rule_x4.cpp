// slice_rule_x4.h: scale, slice_hull and polygon_hull of slice_deriv.h on
// the SoftRounding policy, four lanes at a time.
// The + and − of the policy are avx2_lanes.h's; × and ÷ are those of
// branchless_rounding.h's second family (mul_up, div_up_pos), written here.
#include "sillage/dynamics/slice_rule_x4.h"

#include "sillage/interval/avx2_lanes.h"

namespace sillage::detail {

#if SILLAGE_AVX2_LANES

namespace {

// branchless_rounding.h's mul_up: an upper bound of a·b, 0·inf = 0.
SILLAGE_AVX2_INLINE V soft_mul_up(V a, V b) {
  const V z = set(0.0);
  const V p = _mm256_add_pd(_mm256_mul_pd(a, b), z);
  const V e = fma(a, b, neg(p));
  const M tiny = lt(abs(p), set(0x1p-968));
  return select(eq(a, z) | eq(b, z), z, step_up(p, gt(e, z) | tiny));
}
SILLAGE_AVX2_INLINE V soft_mul_down(V a, V b) { return neg(soft_mul_up(neg(a), b)); }

// branchless_rounding.h's div_up_pos: an upper bound of a / b, a >= 0, b > 0.
SILLAGE_AVX2_INLINE V soft_div_up(V a, V b) {
  const V q = _mm256_add_pd(_mm256_div_pd(a, b), set(0.0));
  const V r = fma(neg(q), b, a);
  const V tiny = set(0x1p-968), huge = set(0x1p1000);
  const M safe = ge(a, tiny) & ge(b, tiny) & ge(q, tiny) & le(b, huge) & le(q, huge);
  const M unsafe{_mm256_xor_pd(safe.m, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)))};
  return step_up(q, (gt(r, set(0.0)) | unsafe) & lt(q, set(rounding::kInf)));
}

// std::min(x, y) is y < x ? y : x, that is vminpd(y, x) (NaN or equal: x); max alike.
SILLAGE_AVX2_INLINE V smin(V x, V y) { return _mm256_min_pd(y, x); }
SILLAGE_AVX2_INLINE V smax(V x, V y) { return _mm256_max_pd(y, x); }

// Four doubles t[k .. k+3] in the lanes order of Quad (0 2 1 3).
SILLAGE_AVX2_INLINE V load_times(const double* t) { return _mm256_permute4x64_pd(_mm256_loadu_pd(t), 0xD8); }

// width and scale (slice_deriv.h): [plo, phi] ⊇ (t1 - t0)·[vv].
SILLAGE_AVX2_INLINE void scale4(V t0, V t1, Quad vv, V& plo, V& phi) {
  const V zero = set(0.0);
  const V wlo = sub_down(t1, t0), whi = sub_up(t1, t0);
  plo = soft_mul_down(vv.lo, select(ge(vv.lo, zero), wlo, whi));
  phi = soft_mul_up(vv.hi, select(ge(vv.hi, zero), whi, wlo));
}

// polygon_hull<SoftRounding, kConsistent> (slice_deriv.h) of four slices
// from their times, gates [a] and [b] and derivative bounds [vv].
template <bool kConsistent>
SILLAGE_AVX2_INLINE void hull4(V t0, V t1, Quad a, Quad b, Quad vv, V& lo, V& up) {
  const V zero = set(0.0), inf = set(rounding::kInf), ninf = set(-rounding::kInf);
  V plo, phi;
  scale4(t0, t1, vv, plo, phi);
  const M st = lt(vv.lo, zero) & gt(vv.hi, zero) & gt(vv.lo, ninf) & lt(vv.hi, inf);  // straddles
  const V inv = soft_div_up(set(1.0), sub_down(vv.hi, vv.lo));
  const V f1d = add_up(a.hi, phi);
  const V f20 = sub_up(b.hi, plo);
  const V mu = smin(smax(a.hi, f1d), smax(b.hi, f20));
  const V du0 = sub_up(f20, a.hi);
  const V du = kConsistent ? du0 : smax(du0, zero);
  const V cu = add_up(a.hi, soft_mul_up(soft_mul_up(vv.hi, inv), du));
  up = smin(mu, select(st, cu, inf));
  const V g1d = add_down(a.lo, plo);
  const V g20 = sub_down(b.lo, phi);
  const V ml = smax(smin(a.lo, g1d), smin(b.lo, g20));
  const V dl0 = sub_down(g20, a.lo);
  const V dl = kConsistent ? dl0 : smin(dl0, zero);
  const V cl = add_down(a.lo, soft_mul_down(soft_mul_up(neg(vv.lo), inv), dl));
  lo = smax(ml, select(st, cl, ninf));
}

}  // namespace

SILLAGE_AVX2 void scaled_derivatives_x4(const double* t, const Interval* v, std::size_t first, std::size_t count,
                                        double* plo, double* phi) {
  for (std::size_t k = first; k + 4 <= first + count; k += 4) {
    V lo, hi;
    scale4(load_times(t + k), load_times(t + k + 1), load(v + k), lo, hi);
    // lanes 0 2 1 3 back to 0 1 2 3
    _mm256_storeu_pd(plo + (k - first), _mm256_permute4x64_pd(lo, 0xD8));
    _mm256_storeu_pd(phi + (k - first), _mm256_permute4x64_pd(hi, 0xD8));
  }
}

SILLAGE_AVX2 std::uint64_t polygon_hulls_x4(const double* t, Interval* s, const Interval* g, const Interval* v,
                                            std::size_t first, std::size_t count) {
  __m256i changed = _mm256_setzero_si256();
  for (std::size_t k = first; k + 4 <= first + count; k += 4) {
    const Quad sl = load(s + k), a = load(g + k), b = load(g + k + 1);
    V lo, up;
    hull4<true>(load_times(t + k), load_times(t + k + 1), a, b, load(v + k), lo, up);
    // hull_into: widening, then the slice
    up = smax(up, smax(a.hi, b.hi));
    lo = smin(lo, smin(a.lo, b.lo));
    const Quad now{smax(sl.lo, lo), smin(sl.hi, up)};
    const __m256i same_lo = _mm256_cmpeq_epi64(_mm256_castpd_si256(now.lo), _mm256_castpd_si256(sl.lo));
    const __m256i same_hi = _mm256_cmpeq_epi64(_mm256_castpd_si256(now.hi), _mm256_castpd_si256(sl.hi));
    changed = _mm256_or_si256(changed, _mm256_andnot_si256(_mm256_and_si256(same_lo, same_hi), _mm256_set1_epi64x(-1)));
    store(s + k, now);
  }
  return static_cast<std::uint64_t>(_mm256_movemask_pd(_mm256_castsi256_pd(changed)));
}

SILLAGE_AVX2 void polygon_hull_bounds_x4(const double* t, const Interval* g, const Interval* v, std::size_t first,
                                         std::size_t count, double* lo, double* up) {
  for (std::size_t k = first; k + 4 <= first + count; k += 4) {
    V l, u;
    hull4<false>(load_times(t + k), load_times(t + k + 1), load(g + k), load(g + k + 1), load(v + k), l, u);
    // lanes 0 2 1 3 back to 0 1 2 3
    _mm256_storeu_pd(lo + (k - first), _mm256_permute4x64_pd(l, 0xD8));
    _mm256_storeu_pd(up + (k - first), _mm256_permute4x64_pd(u, 0xD8));
  }
}

#else

void scaled_derivatives_x4(const double*, const Interval*, std::size_t, std::size_t, double*, double*) {}
std::uint64_t polygon_hulls_x4(const double*, Interval*, const Interval*, const Interval*, std::size_t, std::size_t) {
  return 0;
}
void polygon_hull_bounds_x4(const double*, const Interval*, const Interval*, std::size_t, std::size_t, double*,
                            double*) {}

#endif

}  // namespace sillage::detail
