// CtcIvp on the Van der Pol oscillator (mu = 1): x1' = x2,
// x2' = (1 - x1^2) x2 - x1, t in [0, 5], against a 256-bit MPFR Taylor
// simulation (order 40, step 1/128, truncation far below 1e-30). Every gate
// must contain the reference of a point start, and of the corners and
// centre of a box start (compared exactly with mpfr_cmp_d).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <array>
#include <cmath>
#include <vector>

#include "mpfr_big.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/error.h"

using namespace sillage;

namespace {

using mpfr_ref::Big;
using mpfr_ref::encloses;

// One Taylor step of order P: (k+1) a_{k+1} = b_k,
// (k+1) b_{k+1} = b_k - (a^2 b)_k - a_k, the products by convolution.
using Vdp = std::array<Big, 2>;
void vdp_step(Vdp& s, double h) {
  constexpr int P = 40;
  std::vector<Big> a(P + 1), b(P + 1), sq(P + 1);
  a[0] = s[0], b[0] = s[1];
  Big t, sqb;
  for (int k = 0; k < P; ++k) {
    mpfr_set_zero(sq[k].v, 1);
    for (int j = 0; j <= k; ++j) {
      mpfr_mul(t.v, a[j].v, a[k - j].v, MPFR_RNDN);
      mpfr_add(sq[k].v, sq[k].v, t.v, MPFR_RNDN);
    }
    mpfr_set_zero(sqb.v, 1);
    for (int j = 0; j <= k; ++j) {
      mpfr_mul(t.v, sq[j].v, b[k - j].v, MPFR_RNDN);
      mpfr_add(sqb.v, sqb.v, t.v, MPFR_RNDN);
    }
    mpfr_div_ui(a[k + 1].v, b[k].v, k + 1, MPFR_RNDN);
    mpfr_sub(t.v, b[k].v, sqb.v, MPFR_RNDN);
    mpfr_sub(t.v, t.v, a[k].v, MPFR_RNDN);
    mpfr_div_ui(b[k + 1].v, t.v, k + 1, MPFR_RNDN);
  }
  const Big H(h);
  for (auto* c : {&a, &b}) {
    Big acc = (*c)[P];
    for (int k = P - 1; k >= 0; --k) {
      mpfr_mul(acc.v, acc.v, H.v, MPFR_RNDN);
      mpfr_add(acc.v, acc.v, (*c)[k].v, MPFR_RNDN);
    }
    s[c == &a ? 0 : 1] = acc;
  }
}

const Function kVdp({"x1", "x2"}, "(x2, (1 - x1^2)*x2 - x1)");

// The reference from (x10, x20) at every gate of td (slices of 1/8).
std::vector<Vdp> reference(double x10, double x20, const TDomain& td) {
  std::vector<Vdp> r{{Big(x10), Big(x20)}};
  Vdp s = r.front();
  for (std::size_t k = 0; k < td.nb_slices(); ++k) {
    for (int j = 0; j < 16; ++j) vdp_step(s, 0.125 / 16);  // exact in binary
    r.push_back(s);
  }
  return r;
}

}  // namespace

TEST(CtcIvpVdp, PointStartEnclosesTheReference) {
  auto td = TDomain::create(0.0, 5.0, 0.125);
  TubeVector x(td, 2);
  x.set_gate(0, IntervalVector{Interval(2.0), Interval(0.0)});
  ASSERT_TRUE(CtcIvp(kVdp).contract(x));
  const auto ref = reference(2.0, 0.0, *td);
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
    for (std::size_t i = 0; i < 2; ++i) EXPECT_TRUE(encloses(x.gate(k)[i], ref[k][i])) << k << " " << i;
  }
  EXPECT_LT(x.gate(td->nb_slices()).max_diam(), 1e-10);
}

TEST(CtcIvpVdp, BoxStartEnclosesTheCornersAndTheCentre) {
  auto td = TDomain::create(0.0, 5.0, 0.125);
  TubeVector x(td, 2);
  // A box of 2e-3: its width stays below 1e-2 up to t = 5 (from a box of
  // 0.2 the wrapping of the first-order Lohner form blows up near t = 2).
  x.set_gate(0, IntervalVector{Interval(1.999, 2.001), Interval(-0.001, 0.001)});
  ASSERT_TRUE(CtcIvp(kVdp).contract(x));
  for (const auto& [a, b] : std::vector<std::pair<double, double>>{{1.999, -0.001}, {1.999, 0.001}, {2.001, -0.001},
                                                                     {2.001, 0.001}, {2.0, 0.0}}) {
    const auto ref = reference(a, b, *td);
    for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
      for (std::size_t i = 0; i < 2; ++i) EXPECT_TRUE(encloses(x.gate(k)[i], ref[k][i])) << a << " " << b << " " << k;
    }
  }
  EXPECT_LT(x.gate(td->nb_slices()).max_diam(), 1e-2);
}

namespace {

// Gates 0..K of a run from the 0.2 box around (2, 0) with m pieces.
TubeVector vdp_wide(std::size_t m, const std::shared_ptr<TDomain>& td) {
  TubeVector x(td, 2);
  x.set_gate(0, IntervalVector{Interval(1.9, 2.1), Interval(-0.1, 0.1)});
  CtcIvp ctc(kVdp);
  ctc.set_max_pieces(m);
  EXPECT_TRUE(ctc.contract(x));
  return x;
}

}  // namespace

TEST(CtcIvpVdp, WideBoxWithPiecesEnclosesTheReferencesUpToTheEnd) {
  // From the 0.2 box one set blows up near t = 2.5; up to 64 pieces carry
  // it to t = 5. Checked against the corners, the centre and the middles
  // of the sides (256-bit references), at every gate.
  auto td = TDomain::create(0.0, 5.0, 0.125);
  const TubeVector one = vdp_wide(1, td);
  const TubeVector x = vdp_wide(64, td);
  const std::size_t N = td->nb_slices();
  EXPECT_TRUE(one.gate(N).is_unbounded() || one.gate(N).max_diam() > 1.0);
  EXPECT_LT(x.gate(N).max_diam(), 1.0);
  for (const double a : {1.9, 2.0, 2.1}) {
    for (const double b : {-0.1, 0.0, 0.1}) {
      const auto ref = reference(a, b, *td);
      for (std::size_t k = 0; k <= N; ++k) {
        for (std::size_t i = 0; i < 2; ++i) EXPECT_TRUE(encloses(x.gate(k)[i], ref[k][i])) << a << " " << b << " " << k;
      }
    }
  }
}

TEST(CtcIvpVdp, OnePieceIsTheSingleSetAndZeroIsRefused) {
  auto td = TDomain::create(0.0, 5.0, 0.125);
  TubeVector a(td, 2), b(td, 2);
  const IntervalVector x0{Interval(1.999, 2.001), Interval(-0.001, 0.001)};
  a.set_gate(0, x0);
  b.set_gate(0, x0);
  CtcIvp ctc(kVdp);
  ASSERT_TRUE(ctc.contract(a));
  ctc.set_max_pieces(1);
  ASSERT_TRUE(ctc.contract(b));
  EXPECT_TRUE(a == b);
  EXPECT_EQ(ctc.max_pieces(), 1u);
  // From a point there is nothing to cut: the pieces' sweep is the one set's.
  TubeVector c(td, 2), d(td, 2);
  c.set_gate(0, IntervalVector{Interval(2.0), Interval(0.0)});
  d.set_gate(0, IntervalVector{Interval(2.0), Interval(0.0)});
  ASSERT_TRUE(ctc.contract(c));
  ctc.set_max_pieces(8);
  ASSERT_TRUE(ctc.contract(d));
  EXPECT_TRUE(c == d);
  EXPECT_THROW(ctc.set_max_pieces(0), Error);
}

TEST(CtcIvpVdp, PiecesWithInputsHoldTheExactReachableSet) {
  // x' = -x + u, x(0) ∈ [-1, 1], u(t) ∈ [-0.1, 0.1]: the reachable set at t
  // is [-1, 1]·e^{-t} + [-0.1, 0.1]·(1 - e^{-t}) exactly (extreme constant
  // inputs from the extreme starts). Every piece count must hold it (and
  // stay within 0.05 of it: the inputs are bounded to first order).
  auto td = TDomain::create(0.0, 3.0, 0.25);
  for (const std::size_t m : {1, 2, 8}) {
    TubeVector x(td, 1);
    x.set_gate(0, IntervalVector{Interval(-1, 1)});
    CtcIvp ctc(Function({"x", "u"}, "-x + u"), 1, 12, TimePropag::FORWARD);
    ctc.set_max_pieces(m);
    ASSERT_TRUE(ctc.contract(x, TubeVector(td, 1, Interval(-0.1, 0.1))));
    for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
      const double e = std::exp(-td->t(k)), hi = e + 0.1 * (1 - e);
      EXPECT_LE(x.gate(k)[0].lb(), -hi) << m << " " << k;
      EXPECT_GE(x.gate(k)[0].ub(), hi) << m << " " << k;
      EXPECT_LT(x.gate(k)[0].ub(), hi + 0.05) << m << " " << k;  // the inputs are first order
    }
  }
}
