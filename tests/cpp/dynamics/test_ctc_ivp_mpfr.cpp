// CtcIvp against references computed with MPFR (256 bits): the closed-form
// flows of x' = -sin x and of the harmonic oscillator at the gate times,
// and a high-order Taylor simulation of Lorenz. Every gate must contain the
// reference (compared exactly with mpfr_cmp_d, no rounding to double).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <array>
#include <cmath>

#include "mpfr_big.h"
#include "sillage/dynamics/ctc_ivp.h"

using namespace sillage;

namespace {

using mpfr_ref::Big;
using mpfr_ref::encloses;

// x(t) = 2 atan(e^{-t} tan(x0/2)), t and x0 doubles taken exactly.
Big sin_flow(double x0, double t) {
  Big r(x0), e(-t);
  mpfr_div_ui(r.v, r.v, 2, MPFR_RNDN);
  mpfr_tan(r.v, r.v, MPFR_RNDN);
  mpfr_exp(e.v, e.v, MPFR_RNDN);
  mpfr_mul(r.v, r.v, e.v, MPFR_RNDN);
  mpfr_atan(r.v, r.v, MPFR_RNDN);
  mpfr_mul_ui(r.v, r.v, 2, MPFR_RNDN);
  return r;
}

// Lorenz (10, 28, 8/3) by its Taylor series in MPFR: order 40, fixed step
// h (truncation far below 1e-30 for h = 1/128 here).
using Lz = std::array<Big, 3>;
void lorenz_step(Lz& s, double h) {
  constexpr int P = 40;
  std::array<std::array<Big, P + 1>, 3> c;
  for (int i = 0; i < 3; ++i) c[i][0] = s[i];
  Big beta(8.0), t1, t2, acc;
  mpfr_div_ui(beta.v, beta.v, 3, MPFR_RNDN);
  for (int k = 0; k < P; ++k) {
    // xy_k and xz_k by convolution
    Big xy, xz;
    for (int j = 0; j <= k; ++j) {
      mpfr_mul(t1.v, c[0][j].v, c[1][k - j].v, MPFR_RNDN);
      mpfr_add(xy.v, xy.v, t1.v, MPFR_RNDN);
      mpfr_mul(t1.v, c[0][j].v, c[2][k - j].v, MPFR_RNDN);
      mpfr_add(xz.v, xz.v, t1.v, MPFR_RNDN);
    }
    // (k+1) c_{k+1} = f_k
    mpfr_sub(t1.v, c[1][k].v, c[0][k].v, MPFR_RNDN);
    mpfr_mul_ui(t1.v, t1.v, 10, MPFR_RNDN);
    mpfr_div_ui(c[0][k + 1].v, t1.v, k + 1, MPFR_RNDN);
    mpfr_mul_ui(t1.v, c[0][k].v, 28, MPFR_RNDN);
    mpfr_sub(t1.v, t1.v, xz.v, MPFR_RNDN);
    mpfr_sub(t1.v, t1.v, c[1][k].v, MPFR_RNDN);
    mpfr_div_ui(c[1][k + 1].v, t1.v, k + 1, MPFR_RNDN);
    mpfr_mul(t2.v, beta.v, c[2][k].v, MPFR_RNDN);
    mpfr_sub(t1.v, xy.v, t2.v, MPFR_RNDN);
    mpfr_div_ui(c[2][k + 1].v, t1.v, k + 1, MPFR_RNDN);
  }
  Big H(h);
  for (int i = 0; i < 3; ++i) {
    acc = c[i][P];
    for (int k = P - 1; k >= 0; --k) {
      mpfr_mul(acc.v, acc.v, H.v, MPFR_RNDN);
      mpfr_add(acc.v, acc.v, c[i][k].v, MPFR_RNDN);
    }
    s[i] = acc;
  }
}

}  // namespace

TEST(CtcIvpMpfr, SinEnclosesTheExactFlow) {
  for (double x0 : {1.0, 0.1, 3.0, -2.5}) {
    auto td = TDomain::create(0.0, 10.0, 1.0);
    Tube x(td);
    x.set_gate(0, Interval(x0));
    ASSERT_TRUE(CtcIvp(Function({"x"}, "-sin(x)")).contract(x));
    for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
      EXPECT_TRUE(encloses(x.gate(k), sin_flow(x0, td->t(k)))) << x0 << " " << k;
      EXPECT_LT(x.gate(k).diam(), 1e-12) << x0 << " " << k;
    }
  }
}

TEST(CtcIvpMpfr, OscillatorEnclosesTheExactFlowOver100Periods) {
  const double T = 200 * M_PI;
  auto td = TDomain::create(0.0, T, T / 100);
  TubeVector x(td, 2);
  x.set_gate(0, IntervalVector{Interval(0.0), Interval(1.0)});
  ASSERT_TRUE(CtcIvp(Function({"x1", "x2"}, "(x2, -x1)")).contract(x));
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
    Big s(td->t(k)), c(td->t(k));
    mpfr_sin(s.v, s.v, MPFR_RNDN);
    mpfr_cos(c.v, c.v, MPFR_RNDN);
    EXPECT_TRUE(encloses(x.gate(k)[0], s)) << k;
    EXPECT_TRUE(encloses(x.gate(k)[1], c)) << k;
  }
  EXPECT_LT(x.gate(td->nb_slices()).max_diam(), 1e-10);
}

TEST(CtcIvpMpfr, LorenzEnclosesAHighPrecisionSimulation) {
  auto td = TDomain::create(0.0, 4.0, 0.125);
  TubeVector x(td, 3);
  x.set_gate(0, IntervalVector{Interval(15.0), Interval(15.0), Interval(36.0)});
  ASSERT_TRUE(CtcIvp(Function({"x", "y", "z"}, "(10*(y - x), x*(28 - z) - y, x*y - 8/3*z)")).contract(x));
  Lz s{Big(15.0), Big(15.0), Big(36.0)};
  for (std::size_t k = 1; k <= td->nb_slices(); ++k) {
    for (int j = 0; j < 16; ++j) lorenz_step(s, 0.125 / 16);  // exact in binary
    for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(encloses(x.gate(k)[i], s[i])) << k << " " << i;
  }
  EXPECT_LT(x.gate(td->nb_slices()).max_diam(), 1e-6);
}
