// sin and cos over rows of intervals: one vectorisable pass computes the
// end point values and quadrants of a block, a second (also vectorisable)
// combines them per interval as trig.cpp does; the lanes the kernel does not cover go to the
// scalar functions. The error analysis is in trig_batch.h.
#include "sillage/interval/trig_batch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "sillage/interval/elementary.h"

namespace sillage::detail {

namespace {

constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
// pi/2 = kP1 + kP2 + kP3 + (less than 2^-163).
constexpr double kP1 = 0x1.921fb54442d18p+0, kP2 = 0x1.1a62633145c07p-54, kP3 = -0x1.f1976b7ed8fbcp-110;
constexpr double kRoundMagic = 0x1.8p52;  // (y + 1.5 2^52) - 1.5 2^52 = y rounded to an integer, |y| < 2^51
constexpr double kFastMax = 0x1p18;
constexpr double kTinyR = 0x1p-27;
constexpr double kWiden = 0x1p-50;  // twice the error bound 2^-51 of the values

// (-1)^i / (2i+1)! for i = 1..8 and (-1)^i / (2i)! for i = 2..8, rounded to nearest.
constexpr std::array<double, 8> kSin = {-0x1.5555555555555p-3, 0x1.1111111111111p-7,   -0x1.a01a01a01a01ap-13,
                                        0x1.71de3a556c734p-19, -0x1.ae64567f544e4p-26, 0x1.6124613a86d09p-33,
                                        -0x1.ae7f3e733b81fp-41, 0x1.952c77030ad4ap-49};
constexpr std::array<double, 7> kCos = {0x1.5555555555555p-5,   -0x1.6c16c16c16c17p-10, 0x1.a01a01a01a01ap-16,
                                        -0x1.27e4fb7789f5cp-22, 0x1.1eed8eff8d898p-29,  -0x1.93974a8c07c9dp-37,
                                        0x1.ae7f3e733b81fp-45};

// c[0] + c[1] z + ... + c[N-1] z^(N-1) by Horner's rule, one fma per step:
// one rounding where the error analysis counts two (a multiplication and an
// addition), so its bounds hold, in half the instructions.
template <std::size_t N>
[[gnu::always_inline]] inline double horner(double z, const std::array<double, N>& c) {
  double s = c[N - 1];
  for (std::size_t i = N - 1; i-- > 0;) s = std::fma(s, z, c[i]);
  return s;
}

// The kernel of trig_values; `shift` 0 for sin, 1 for cos (cos x = sin(x + pi/2)).
// Written without branches so that the compiler vectorises it; GCC turns the
// selections on comparisons into blends only when comparisons may not trap
// (no flag of the floating-point environment is read in sillage; the values
// and their rounding are unchanged).
[[gnu::noinline, gnu::optimize("no-trapping-math")]] void values(const double* x, std::size_t n, double shift,
                                                                double* lo, double* hi, double* quadrant, double* fast) {
  for (std::size_t i = 0; i < n; ++i) {
    const bool in_range = std::fabs(x[i]) <= kFastMax;  // false for inf and NaN
    const double xs = in_range ? x[i] : 1.0;             // keeps the other lanes finite
    const double k = (xs * kTwoOverPi + kRoundMagic) - kRoundMagic;
    const double t1 = std::fma(-k, kP1, xs);  // exact
    const double p2 = k * kP2, e2 = std::fma(k, kP2, -p2);
    const double rh = t1 - p2, bv = rh - t1;
    const double e = (t1 - (rh - bv)) + (-p2 - bv);  // 2Sum: t1 - p2 = rh + e exactly
    const double rl = (e - e2) - k * kP3;
    const double z = rh * rh;
    const double sin_r = rh + ((rh * z) * horner(z, kSin) + rl * (1.0 - 0.5 * z));
    const double cos_r = 1.0 + (z * (-0.5 + z * horner(z, kCos)) - rh * rl);
    const double q = k - 4.0 * std::floor(k * 0.25);  // k mod 4, exact
    double m = q + shift;
    m = m >= 4.0 ? m - 4.0 : m;
    double v = (m == 1.0) | (m == 3.0) ? cos_r : sin_r;
    v = m >= 2.0 ? -v : v;
    const double d = std::fabs(v) * kWiden;
    lo[i] = v - d;
    hi[i] = v + d;
    const double fq = rh < 0 ? q - 1.0 : q;  // floor(x / (pi/2)) mod 4: r has the sign of rh
    quadrant[i] = fq < 0 ? 3.0 : fq;
    fast[i] = in_range & (std::fabs(rh) >= kTinyR) ? 1.0 : 0.0;
  }
}

constexpr std::size_t kBlock = 64;  // intervals per pass (two end points each)

// trig.cpp's case analysis of sin (kCos false) or cos on the kernel's values
// of the end points a[j] (index j) and b[j] (index m + j), for j < m:
// branch-free on doubles (quadrants 0..3), so that the compiler vectorises it.
// Written out without calls (std::min, lambdas): a function with optimize()
// attributes inlines none, and a loop with calls does not vectorise; and
// with __restrict, as GCC gives up on checking the overlap of seven arrays.
template <bool kCos>
[[gnu::noinline, gnu::optimize("no-trapping-math")]] void combine(const double* __restrict ends,
                                                                 const double* __restrict lo,
                                                                 const double* __restrict hi,
                                                                 const double* __restrict quad, std::size_t m,
                                                                 double* __restrict rl, double* __restrict rh) {
  // Maximum 1 leaving quadrant 0 (sin) / 3 (cos), minimum -1 leaving 2 / 1.
  constexpr double kMinQuadrant = kCos ? 1.0 : 2.0, kMaxQuadrant = kCos ? 3.0 : 0.0;
  for (std::size_t j = 0; j < m; ++j) {
    const double a = ends[j], b = ends[m + j], qa = quad[j], qb = quad[m + j];
    // Boundaries k pi/2 crossed: (qb - qa) mod 4, or 4 (all) when [a, b]
    // may hold four more (see crossings() in trig.cpp); quadrant q is left
    // when (q - qa) mod 4 < crossed.
    const double turns = qb - qa < 0 ? qb - qa + 4.0 : qb - qa;
    const double crossed = (b - a) * kTwoOverPi > turns + 2.5 ? 4.0 : turns;
    const double to_min = kMinQuadrant - qa < 0 ? kMinQuadrant - qa + 4.0 : kMinQuadrant - qa;
    const double to_max = kMaxQuadrant - qa < 0 ? kMaxQuadrant - qa + 4.0 : kMaxQuadrant - qa;
    // std::min(x, y) is y < x ? y : x, std::max(x, y) is x < y ? y : x.
    double l = to_min < crossed ? -1.0 : (lo[m + j] < lo[j] ? lo[m + j] : lo[j]);
    double h = to_max < crossed ? 1.0 : (hi[j] < hi[m + j] ? hi[m + j] : hi[j]);
    if constexpr (!kCos) {  // the same bounds by sign and size of x as trig.cpp's sin
      h = a >= 0 && b < h ? b : h;
      l = b <= 0 && l < a ? a : l;
      l = a >= 0 && b <= 3 && l < 0.0 ? 0.0 : l;
      h = b <= 0 && a >= -3 && 0.0 < h ? 0.0 : h;
    }
    rl[j] = (l < -1.0 ? -1.0 : l) + 0.0;
    rh[j] = (1.0 < h ? 1.0 : h) + 0.0;
  }
}

// Whether every flag of the kernel is 1.0 (0.0 is the other value): an AND of
// the bit patterns, which vectorises where a scalar test per lane costs as much
// as the kernel's combination (the scalar fallback is rare).
inline bool all_fast(const double* fast, std::size_t n) {
  std::uint64_t all = ~std::uint64_t{0};
  for (std::size_t i = 0; i < n; ++i) all &= std::bit_cast<std::uint64_t>(fast[i]);
  return all == std::bit_cast<std::uint64_t>(1.0);
}

// Rows of sin (kCos false) or cos; the lanes the kernel does not cover by the scalar functions.
template <bool kCos>
void rows(const Interval* x, Interval* r, std::size_t n) {
  double ends[2 * kBlock], lo[2 * kBlock], hi[2 * kBlock], quad[2 * kBlock], fast[2 * kBlock];
  double rl[kBlock], rh[kBlock];
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t m = std::min(kBlock, n - start);
    const Interval* xb = x + start;
    Interval* rb = r + start;
    for (std::size_t j = 0; j < m; ++j) {
      ends[j] = xb[j].lb();
      ends[m + j] = xb[j].ub();
    }
    values(ends, 2 * m, kCos ? 1.0 : 0.0, lo, hi, quad, fast);
    combine<kCos>(ends, lo, hi, quad, m, rl, rh);
    for (std::size_t j = 0; j < m; ++j) rb[j] = Interval::from_bounds_unchecked(rl[j], rh[j]);
    if (all_fast(fast, 2 * m)) continue;
    for (std::size_t j = 0; j < m; ++j) {
      if (fast[j] + fast[m + j] == 2.0) continue;
      const Interval xj = Interval::from_bounds_unchecked(ends[j], ends[m + j]);  // rb may be xb
      rb[j] = kCos ? cos(xj) : sin(xj);
    }
  }
}

}  // namespace

void sin_rows(const Interval* x, Interval* r, std::size_t n) { rows<false>(x, r, n); }
void cos_rows(const Interval* x, Interval* r, std::size_t n) { rows<true>(x, r, n); }

void trig_values(const double* x, std::size_t n, bool cosine, double* lo, double* hi, double* quadrant,
                 double* fast) {
  values(x, n, cosine ? 1.0 : 0.0, lo, hi, quadrant, fast);
}

}  // namespace sillage::detail
