#pragma once
// sin and cos over rows of intervals (internal header): the rows of the
// batch evaluator (expr/batch.cpp). r[i] encloses f(x[i]), as sin(x[i]) /
// cos(x[i]) of elementary.h does, but the end point values come from a
// vectorisable kernel of our own instead of one libm call each.
//
// Fast lanes: both ends finite, |x| <= 2^18 and at least 2^-27 away from a
// multiple of pi/2 (after the reduction). Other lanes (empty, unbounded,
// huge, next to a zero of sin x or cos x) get the scalar functions, which
// reduce exactly there. A fast lane is at most ~8 ulps wider than the exact
// image per bound (relative widening 2^-50), where the scalar function is
// within 2-3: results are not those of elementary.h bit for bit.
//
// Value kernel (trig_batch.cpp), with u = 2^-53:
//  - k = round(x 2/pi), r = x - k pi/2 = t1 - k P2 - k P3 - k P4 where
//    pi/2 = P1 + P2 + P3 + P4 (P1..P3 doubles, |P4| < 2^-163): t1 =
//    fma(-k, P1, x) is exact (x - k P1 is a multiple of ulp(x) or of 2^-53,
//    below 1 in magnitude); k P2 = p2 + e2 exactly (fma); t1 - p2 = rh + e
//    exactly (2Sum); rl = (e - e2) - k P3 in double. For |x| <= 2^18 and
//    |rh| >= 2^-27 the error of rh + rl is below 2^-105 |rh| + 2^-140, i.e.
//    2^-100 |r|, and |rl| <= 1.01 u |rh|; |r| <= pi/4 + 2^-34 < 0.8.
//  - sin r = rh + (rh z S(z) + rl (1 - z/2)), z = rh^2, S the Taylor
//    polynomial -1/3! + z/5! - ... + z^7/17! (coefficients rounded to
//    nearest). Truncation: |r|^19/19! <= 2^-62.5 |r|. Rounding: S within
//    2.2u relative (coefficient -1/6 dominates), rh z S within 5.2u relative
//    of a term <= 0.107 |rh|, i.e. 0.56u |rh|; the rl term 0.04u |rh|; the
//    two last additions 0.11u |rh| + u |sin r|. With |r| <= |sin r| / 0.896:
//    at most 1.8u |sin r|.
//  - cos r = 1 + (z (-1/2 + z C(z)) - rh rl), C the Taylor polynomial
//    1/4! - z/6! + ... + z^6/16!. Truncation 0.8^18/18! < 0.03u; z C within
//    0.11u, the sum with -1/2 0.5u, times z (rounded, z within u): W within
//    1.03u absolute; -rh rl for -rl sin rh: 0.14u; the last two roundings
//    0.33u + 0.5u. At most 2.1u absolute with cos r >= 0.69: 3.1u relative.
//  - Hence |v - f(x)| <= 4u |f(x)| (4u = 2^-51, with margin) and the bounds
//    RN(v -+ 2^-50 |v|) are outward: the rounding of that subtraction (u|v|)
//    stays below the 2^-50 |v| - 2^-51 |f(x)| to spare.
// tests/cpp/interval/test_mpfr_trig_batch.cpp checks the kernel's error and
// the enclosures against MPFR.
#include <cstddef>

#include "sillage/interval/interval.h"

namespace sillage::detail {

// r[i] = an enclosure of sin(x[i]) for i < n (r may be x).
void sin_rows(const Interval* x, Interval* r, std::size_t n);
// r[i] = an enclosure of cos(x[i]) for i < n (r may be x).
void cos_rows(const Interval* x, Interval* r, std::size_t n);

// The value kernel alone, for tests: lo[i] <= sin(x[i]) <= hi[i] (or cos
// when cosine), fast[i] = 0 where x[i] is not a fast lane (lo, hi then
// meaningless); quadrant[i] = floor(x[i] / (pi/2)) mod 4 on fast lanes.
void trig_values(const double* x, std::size_t n, bool cosine, double* lo, double* hi, double* quadrant,
                 double* fast);

}  // namespace sillage::detail
