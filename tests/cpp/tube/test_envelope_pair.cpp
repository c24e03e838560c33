// EnvelopePair::upper (tube/envelope_pair.h) gives, in each lane, the bits of
// upper_envelope<SoftRounding> (slice_deriv.h): on random and adversarial
// operands (infinite slopes and bounds, zeros, tiny and huge values, signs of
// the slopes that make the crossing invalid), zero signs included.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "sillage/interval/rounding_policies.h"
#include "sillage/tube/envelope_pair.h"
#include "sillage/tube/slice_deriv.h"

#if SILLAGE_PAIR_LANES

using namespace sillage;
using detail::PairLanes;

namespace {

struct Args {
  double A, B, P, Q, tau_lo, tau_hi, sig_lo, sig_hi, delta;
};

bool same(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

// Lane 0 holds a, lane 1 holds b (the two calls of LocalSlice::hull share the times).
void check(const Args& a, const Args& b, int& failures) {
  const auto scalar = [](const Args& x, const Args& t) {
    return detail::upper_envelope<detail::SoftRounding>(x.A, x.B, x.P, x.Q, t.tau_lo, t.tau_hi, t.sig_lo, t.sig_hi,
                                                        t.delta);
  };
  const PairLanes::P e = detail::EnvelopePair::upper(PairLanes::make(a.A, b.A), PairLanes::make(a.B, b.B),
                                                     PairLanes::make(a.P, b.P), PairLanes::make(a.Q, b.Q), a.tau_lo,
                                                     a.tau_hi, a.sig_lo, a.sig_hi, a.delta);
  const double want0 = scalar(a, a), want1 = scalar(b, a);
  if ((!same(PairLanes::lane0(e), want0) || !same(PairLanes::lane1(e), want1)) && ++failures <= 20) {
    ADD_FAILURE() << "A " << a.A << " B " << a.B << " P " << a.P << " Q " << a.Q << " / A " << b.A << " B " << b.B
                  << " P " << b.P << " Q " << b.Q << ": " << PairLanes::lane0(e) << " vs " << want0 << ", "
                  << PairLanes::lane1(e) << " vs " << want1;
  }
}

}  // namespace

TEST(EnvelopePair, EachLaneIsTheScalarEnvelopeBitForBit) {
  const double inf = rounding::kInf, tiny = std::numeric_limits<double>::denorm_min();
  // Bounds of non-empty sets as the callers pass them: A, B, P > -inf, Q < +inf.
  const std::vector<double> bounds = {-1e300, -3.0, -0x1p-1000, -tiny, 0.0, tiny, 0x1p-970, 0.1, 1.0, 7.5, 1e300, inf};
  const std::vector<double> slopes = {-inf, -1e300, -2.0, -0x1p-975, -0x1p-1000, 0.0, 0x1p-1000, 0x1p-975, 0.5, 3.0,
                                      1e300, inf};
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto times = [&] {
    const double delta = 0.01 + u(rng), c1 = delta * u(rng), c2 = c1 + (delta - c1) * u(rng);
    return Args{0, 0, 0, 0, c1, c2, delta - c2, delta - c1, delta};
  };
  int failures = 0;
  for (double A : bounds)
    for (double B : bounds)
      for (double P : slopes)
        for (double Q : slopes) {
          if (Q > P || P == -inf || Q == inf) continue;  // Q <= P, P > -inf, Q < +inf
          Args a = times();
          a.A = A, a.B = B, a.P = P, a.Q = Q;
          Args b = a;
          b.A = B, b.B = A, b.P = -Q, b.Q = -P;  // the mirrored call's lane
          check(a, b, failures);
        }
  for (int i = 0; i < 200'000; ++i) {  // slices of a tube around a trajectory
    Args a = times();
    const double x = 10 * (u(rng) - 0.5), r = 0.5 * u(rng), v = 4 * (u(rng) - 0.5), s = 2 * u(rng);
    a.A = x + r, a.B = x + v * a.delta + r + 0.1 * u(rng), a.P = v + s, a.Q = v - s * u(rng);
    Args b = a;
    b.A = -(x - r), b.B = -(x + v * a.delta - r), b.P = -(v - s), b.Q = -(v + s * u(rng));
    if (b.Q > b.P) std::swap(b.P, b.Q);
    check(a, b, failures);
  }
  EXPECT_EQ(failures, 0);
}

#endif
