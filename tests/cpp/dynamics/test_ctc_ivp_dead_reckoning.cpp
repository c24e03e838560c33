// CtcIvp on dead reckoning (thesis 3.4) against 256-bit MPFR references of
// extreme inputs: the noise n(t) ∈ [-1/1000, 1/1000]² constant at a corner,
// or switching corners at t = 32 (a differential inclusion: the contractor
// must cover every measurable input, bang-bang ones included), from the
// corners of the initial box. With piecewise constant noise the heading and
// speed have closed forms,
//   x3(t) = x3(0) - 9/4 sin(t/5) + ∫n1,   x4(t) = x4(0) + t/10 + 4 - 4 cos(t/4) + ∫n2,
// and x1, x2 are quadratures of x4 cos x3, x4 sin x3 (Romberg in MPFR on
// 8-second chunks, its last extrapolation changing less than 1e-15: far
// below the enclosures' widths, about 10).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <array>
#include <vector>

#include "../../../examples/cpp/dead_reckoning_ivp.h"
#include "mpfr_big.h"

using namespace sillage;

namespace {

using mpfr_ref::Big;
using mpfr_ref::encloses;

struct Extreme {
  double x1, x2, x3_err, x4;   // x3(0) = π/2 + x3_err
  double n1a, n2a, n1b, n2b;   // noise before and after t = 32
};

constexpr double kSwitch = 32.0;

// x3(t), x4(t) in MPFR for the extreme e.
void heading_speed(const Extreme& e, const Big& t, Big& x3, Big& x4) {
  Big a, b, pi;
  mpfr_const_pi(pi.v, MPFR_RNDN);
  mpfr_div_ui(x3.v, pi.v, 2, MPFR_RNDN);
  mpfr_set_d(a.v, e.x3_err, MPFR_RNDN);
  mpfr_add(x3.v, x3.v, a.v, MPFR_RNDN);
  mpfr_div_ui(a.v, t.v, 5, MPFR_RNDN);
  mpfr_sin(a.v, a.v, MPFR_RNDN);
  mpfr_mul_d(a.v, a.v, 2.25, MPFR_RNDN);
  mpfr_sub(x3.v, x3.v, a.v, MPFR_RNDN);
  mpfr_set_d(x4.v, e.x4 + 4.0, MPFR_RNDN);
  mpfr_div_ui(a.v, t.v, 10, MPFR_RNDN);
  mpfr_add(x4.v, x4.v, a.v, MPFR_RNDN);
  mpfr_div_ui(a.v, t.v, 4, MPFR_RNDN);
  mpfr_cos(a.v, a.v, MPFR_RNDN);
  mpfr_mul_ui(a.v, a.v, 4, MPFR_RNDN);
  mpfr_sub(x4.v, x4.v, a.v, MPFR_RNDN);
  // ∫_0^t n: n_a up to the switch, n_b after.
  Big before(kSwitch), after;
  if (mpfr_cmp_d(t.v, kSwitch) < 0) mpfr_set(before.v, t.v, MPFR_RNDN);
  mpfr_sub_d(after.v, t.v, kSwitch, MPFR_RNDN);
  if (mpfr_sgn(after.v) < 0) mpfr_set_zero(after.v, 1);
  for (int i = 0; i < 2; ++i) {
    Big& x = i == 0 ? x3 : x4;
    mpfr_mul_d(a.v, before.v, i == 0 ? e.n1a : e.n2a, MPFR_RNDN);
    mpfr_mul_d(b.v, after.v, i == 0 ? e.n1b : e.n2b, MPFR_RNDN);
    mpfr_add(x.v, x.v, a.v, MPFR_RNDN);
    mpfr_add(x.v, x.v, b.v, MPFR_RNDN);
  }
}

// (x4 cos x3, x4 sin x3) at t.
std::array<Big, 2> velocity(const Extreme& e, const Big& t) {
  Big x3, x4;
  heading_speed(e, t, x3, x4);
  std::array<Big, 2> v;
  mpfr_sin_cos(v[1].v, v[0].v, x3.v, MPFR_RNDN);
  mpfr_mul(v[0].v, v[0].v, x4.v, MPFR_RNDN);
  mpfr_mul(v[1].v, v[1].v, x4.v, MPFR_RNDN);
  return v;
}

// ∫_a^b velocity by Romberg (2^L trapezoids, L levels of extrapolation);
// the integrand is analytic on [a, b] (no switch inside).
std::array<Big, 2> romberg(const Extreme& e, double a, double b, double& change) {
  constexpr int L = 9;
  std::array<std::array<std::array<Big, L + 1>, L + 1>, 2> R;
  const Big A(a), B(b);
  Big h, t, s;
  mpfr_sub(h.v, B.v, A.v, MPFR_RNDN);
  const auto fa = velocity(e, A), fb = velocity(e, B);
  for (int c = 0; c < 2; ++c) {
    mpfr_add(R[c][0][0].v, fa[c].v, fb[c].v, MPFR_RNDN);
    mpfr_mul(R[c][0][0].v, R[c][0][0].v, h.v, MPFR_RNDN);
    mpfr_div_ui(R[c][0][0].v, R[c][0][0].v, 2, MPFR_RNDN);
  }
  for (int l = 1; l <= L; ++l) {
    mpfr_div_ui(h.v, h.v, 2, MPFR_RNDN);  // the new trapezoid width
    std::array<Big, 2> sum;
    for (long j = 1; j < (1L << l); j += 2) {
      mpfr_mul_si(t.v, h.v, j, MPFR_RNDN);
      mpfr_add(t.v, t.v, A.v, MPFR_RNDN);
      const auto f = velocity(e, t);
      for (int c = 0; c < 2; ++c) mpfr_add(sum[c].v, sum[c].v, f[c].v, MPFR_RNDN);
    }
    for (int c = 0; c < 2; ++c) {
      mpfr_mul(s.v, sum[c].v, h.v, MPFR_RNDN);
      mpfr_div_ui(R[c][l][0].v, R[c][l - 1][0].v, 2, MPFR_RNDN);
      mpfr_add(R[c][l][0].v, R[c][l][0].v, s.v, MPFR_RNDN);
      for (int k = 1; k <= l; ++k) {  // R[l][k] = R[l][k-1] + (R[l][k-1] - R[l-1][k-1]) / (4^k - 1)
        mpfr_sub(s.v, R[c][l][k - 1].v, R[c][l - 1][k - 1].v, MPFR_RNDN);
        mpfr_div_ui(s.v, s.v, (1UL << (2 * k)) - 1, MPFR_RNDN);
        mpfr_add(R[c][l][k].v, R[c][l][k - 1].v, s.v, MPFR_RNDN);
      }
    }
  }
  for (int c = 0; c < 2; ++c) {
    mpfr_sub(s.v, R[c][L][L].v, R[c][L - 1][L - 1].v, MPFR_RNDN);
    change = std::max(change, std::abs(mpfr_get_d(s.v, MPFR_RNDN)));
  }
  return {R[0][L][L], R[1][L][L]};
}

std::vector<Extreme> extremes() {
  std::vector<Extreme> out;
  const double n = 1e-3;
  for (int k = 0; k < 8; ++k) {
    const double s3 = k & 1 ? 0.01 : -0.01, s4 = k & 2 ? 0.01 : -0.01;
    const double na = k & 4 ? n : -n, nb = k & 2 ? -n : n;
    const double p = k % 3 == 0 ? 1.0 : -1.0;
    out.push_back({p, -p, s3, s4, na, nb, na, nb});   // constant noise
    out.push_back({-p, p, s3, s4, na, nb, -na, -nb});  // switching at t = 32
  }
  return out;
}

}  // namespace

TEST(CtcIvpDeadReckoning, EnclosesMpfrExtremesAndBeatsTheLinearisedResolution) {
  const auto td = TDomain::create(0.0, 64.0, 0.5);
  const TubeVector u(td, 2, dead_reckoning::ivp_noise());
  const CtcIvp ctc = dead_reckoning::ivp_contractor();
  TubeVector x(td, 5);
  x.set_gate(0, dead_reckoning::ivp_initial_gate());
  ASSERT_TRUE(ctc.contract(x, u));
  double change = 0.0;
  for (const Extreme& e : extremes()) {
    Big p1(e.x1), p2(e.x2);
    for (std::size_t k = 16; k <= td->nb_slices(); k += 16) {  // every 8 s; t = 32 is a chunk end
      const auto d = romberg(e, td->t(k - 16), td->t(k), change);
      mpfr_add(p1.v, p1.v, d[0].v, MPFR_RNDN);
      mpfr_add(p2.v, p2.v, d[1].v, MPFR_RNDN);
      Big x3, x4;
      heading_speed(e, Big(td->t(k)), x3, x4);
      EXPECT_TRUE(encloses(x.gate(k)[0], p1)) << k;
      EXPECT_TRUE(encloses(x.gate(k)[1], p2)) << k;
      EXPECT_TRUE(encloses(x.gate(k)[2], x3)) << k;
      EXPECT_TRUE(encloses(x.gate(k)[3], x4)) << k;
    }
  }
  EXPECT_LT(change, 1e-15);  // the quadratures converged
  // The example's linearised resolution (examples/cpp/dead_reckoning.cpp) is
  // [33.09, 43.56] × [48.36, 57.77]; the sampled hull about [33.94, 42.87] ×
  // [49.98, 56.10].
  const IntervalVector end = x.gate(td->nb_slices());
  EXPECT_TRUE(end[0].is_subset(Interval(33.09, 43.56))) << end;
  EXPECT_TRUE(end[1].is_subset(Interval(48.36, 57.77))) << end;
}
