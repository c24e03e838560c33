#include "sillage/dynamics/polygon_hull_x8.h"

#if SILLAGE_HARD_ROUNDING

#include <immintrin.h>

#include <type_traits>

// Only intrinsics below (always inlined): no other inline function is
// compiled for AVX-512 in this file, so nothing AVX-512 leaks to callers.
#define SILLAGE_X8 __attribute__((target("avx512f")))

// GCC 12's *_round_pd intrinsics start from _mm512_undefined_pd() and
// trigger -Wmaybe-uninitialized in its own header: not ours to fix.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace sillage::detail {

static_assert(sizeof(Interval) == 2 * sizeof(double) && std::is_standard_layout_v<Interval>,
              "Interval must be two contiguous doubles (lb, ub)");

namespace {

constexpr int kUp = _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC;
constexpr int kDown = _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC;

// 8 intervals stored as (lb, ub) pairs, split into bounds and back.
struct Pairs {
  __m512d lo, hi;
};

SILLAGE_X8 inline Pairs load_pairs(const Interval* p, __mmask8 m0, __mmask8 m1) {
  const auto* d = reinterpret_cast<const double*>(p);
  const __m512d z0 = _mm512_maskz_loadu_pd(m0, d), z1 = _mm512_maskz_loadu_pd(m1, d + 8);
  const __m512i even = _mm512_set_epi64(14, 12, 10, 8, 6, 4, 2, 0), odd = _mm512_set_epi64(15, 13, 11, 9, 7, 5, 3, 1);
  return {_mm512_permutex2var_pd(z0, even, z1), _mm512_permutex2var_pd(z0, odd, z1)};
}

// The std::min / std::max of the scalar code, operand order included:
// std::min(x, y) = y < x ? y : x = vminpd(y, x) (NaN: x), same for max.
SILLAGE_X8 inline __m512d smin(__m512d x, __m512d y) { return _mm512_min_pd(y, x); }
SILLAGE_X8 inline __m512d smax(__m512d x, __m512d y) { return _mm512_max_pd(y, x); }

}  // namespace

SILLAGE_X8 std::uint64_t polygon_hulls_x8(const double* t, Interval* s, const Interval* g, const Interval* v,
                                          std::size_t first, std::size_t count) {
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
  const __m512d inf = _mm512_set1_pd(rounding::kInf), ninf = _mm512_set1_pd(-rounding::kInf);
  const __m512i to_pairs0 = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0);
  const __m512i to_pairs1 = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
  std::uint64_t changed = 0;
  for (std::size_t k = first; k < first + count; k += 8) {
    const std::size_t n = first + count - k < 8 ? first + count - k : 8;
    const auto m = static_cast<__mmask8>((1u << n) - 1);                    // lanes in use
    const auto m0 = static_cast<__mmask8>(n >= 4 ? 0xFF : (1u << 2 * n) - 1);  // pairs 0..3
    const auto m1 = static_cast<__mmask8>(n <= 4 ? 0 : (1u << 2 * (n - 4)) - 1);  // pairs 4..7
    const Pairs sl = load_pairs(s + k, m0, m1), a = load_pairs(g + k, m0, m1), b = load_pairs(g + k + 1, m0, m1),
                vv = load_pairs(v + k, m0, m1);
    const __m512d t0 = _mm512_maskz_loadu_pd(m, t + k), t1 = _mm512_maskz_loadu_pd(m, t + k + 1);
    // width and δ[v] (scale in slice_deriv.h)
    const __m512d wlo = _mm512_sub_round_pd(t1, t0, kDown), whi = _mm512_sub_round_pd(t1, t0, kUp);
    const __mmask8 vlo_pos = _mm512_cmp_pd_mask(vv.lo, zero, _CMP_GE_OQ);
    const __mmask8 vhi_pos = _mm512_cmp_pd_mask(vv.hi, zero, _CMP_GE_OQ);
    const __m512d plo = _mm512_mul_round_pd(vv.lo, _mm512_mask_blend_pd(vlo_pos, whi, wlo), kDown);
    const __m512d phi = _mm512_mul_round_pd(vv.hi, _mm512_mask_blend_pd(vhi_pos, wlo, whi), kUp);
    // straddles(vlo, vhi)
    const __mmask8 st = _mm512_cmp_pd_mask(vv.lo, zero, _CMP_LT_OQ) & _mm512_cmp_pd_mask(vv.hi, zero, _CMP_GT_OQ) &
                        _mm512_cmp_pd_mask(vv.lo, ninf, _CMP_GT_OQ) & _mm512_cmp_pd_mask(vv.hi, inf, _CMP_LT_OQ);
    // polygon_hull<HardRounding, true>
    const __m512d inv = _mm512_div_round_pd(one, _mm512_sub_round_pd(vv.hi, vv.lo, kDown), kUp);
    const __m512d f1d = _mm512_add_round_pd(a.hi, phi, kUp);
    const __m512d f20 = _mm512_sub_round_pd(b.hi, plo, kUp);
    const __m512d mu = smin(smax(a.hi, f1d), smax(b.hi, f20));
    const __m512d du = _mm512_sub_round_pd(f20, a.hi, kUp);
    const __m512d cu = _mm512_add_round_pd(
        a.hi, _mm512_mul_round_pd(_mm512_mul_round_pd(vv.hi, inv, kUp), du, kUp), kUp);
    __m512d up = smin(mu, _mm512_mask_blend_pd(st, inf, cu));
    const __m512d g1d = _mm512_add_round_pd(a.lo, plo, kDown);
    const __m512d g20 = _mm512_sub_round_pd(b.lo, phi, kDown);
    const __m512d ml = smax(smin(a.lo, g1d), smin(b.lo, g20));
    const __m512d dl = _mm512_sub_round_pd(g20, a.lo, kDown);
    const __m512d neg_vlo = _mm512_castsi512_pd(  // -vlo: flip the sign bit, as the scalar negation
        _mm512_xor_si512(_mm512_castpd_si512(vv.lo), _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ull))));
    const __m512d cl = _mm512_add_round_pd(
        a.lo, _mm512_mul_round_pd(_mm512_mul_round_pd(neg_vlo, inv, kUp), dl, kDown), kDown);
    __m512d lo = smax(ml, _mm512_mask_blend_pd(st, ninf, cl));
    // widening (kWiden), then the slice
    up = smax(up, smax(a.hi, b.hi));
    lo = smin(lo, smin(a.lo, b.lo));
    const __m512d shi = smin(sl.hi, up), slo = smax(sl.lo, lo);
    const __m512d z0 = _mm512_permutex2var_pd(slo, to_pairs0, shi), z1 = _mm512_permutex2var_pd(slo, to_pairs1, shi);
    auto* d = reinterpret_cast<double*>(s + k);
    const __m512d old0 = _mm512_maskz_loadu_pd(m0, d), old1 = _mm512_maskz_loadu_pd(m1, d + 8);
    changed |= _mm512_mask_cmpneq_epi64_mask(m0, _mm512_castpd_si512(z0), _mm512_castpd_si512(old0));
    changed |= _mm512_mask_cmpneq_epi64_mask(m1, _mm512_castpd_si512(z1), _mm512_castpd_si512(old1));
    _mm512_mask_storeu_pd(d, m0, z0);
    _mm512_mask_storeu_pd(d + 8, m1, z1);
  }
  return changed;
}

}  // namespace sillage::detail

#endif  // SILLAGE_HARD_ROUNDING
