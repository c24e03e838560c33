// CtcIvp: validated integration on tubes, against closed-form flows and
// sampled true trajectories (never lost), with the contractor laws.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "sillage/testing/contractor_kit.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/dynamics/ivp_memory.h"
#include "sillage/error.h"
#include "sillage/interval/elementary.h"

using namespace sillage;

namespace {

// x' = -sin x: x(t) = 2 atan(e^{-t} tan(x0/2)), enclosed in interval arithmetic.
Interval sin_flow(double x0, const Interval& t) {
  return Interval(2.0) * atan(exp(-t) * tan(Interval(x0) / Interval(2.0)));
}

// A non-validated reference: RK4 in long double with a fine step (its error,
// ~1e-16, is far below the widths compared to it).
template <std::size_t N>
using State = std::array<long double, N>;
template <std::size_t N>
State<N> rk4(const std::function<State<N>(const State<N>&)>& f, State<N> x, long double t, int steps) {
  const long double h = t / steps;
  for (int s = 0; s < steps; ++s) {
    State<N> k1 = f(x), y = x;
    for (std::size_t i = 0; i < N; ++i) y[i] = x[i] + h / 2 * k1[i];
    State<N> k2 = f(y);
    for (std::size_t i = 0; i < N; ++i) y[i] = x[i] + h / 2 * k2[i];
    State<N> k3 = f(y);
    for (std::size_t i = 0; i < N; ++i) y[i] = x[i] + h * k3[i];
    State<N> k4 = f(y);
    for (std::size_t i = 0; i < N; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return x;
}

}  // namespace

TEST(CtcIvp, SinMatchesTheClosedForm) {
  auto td = TDomain::create(0.0, 10.0, 0.5);
  Tube x(td);
  x.set_gate(0, Interval(1.0));
  ASSERT_TRUE(CtcIvp(Function({"x"}, "-sin(x)")).contract(x));
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
    EXPECT_TRUE(x.gate(k).intersects(sin_flow(1.0, Interval(td->t(k))))) << k;
    EXPECT_LT(x.gate(k).diam(), 1e-13) << k;
  }
  for (std::size_t k = 0; k < td->nb_slices(); ++k) {
    EXPECT_TRUE(sin_flow(1.0, td->slice_domain(k)).intersects(x.slice(k)));
    for (int j = 1; j < 8; ++j) {
      const double t = td->t(k) + j * (td->t(k + 1) - td->t(k)) / 8;
      EXPECT_TRUE(x.slice(k).intersects(sin_flow(1.0, Interval(t)))) << k;
    }
    EXPECT_LT(x.slice(k).diam(), 0.5);
  }
}

TEST(CtcIvp, SinBackwardFromTheLastGate) {
  auto td = TDomain::create(0.0, 3.0, 0.25);
  Tube x(td);
  const Interval end = sin_flow(2.0, Interval(3.0));
  x.set_gate(td->nb_slices(), end);
  ASSERT_TRUE(CtcIvp(Function({"x"}, "-sin(x)")).contract(x));
  EXPECT_TRUE(x.gate(0).contains(2.0)) << x.gate(0);
  EXPECT_LT(x.gate(0).diam(), 1e-10);
}

TEST(CtcIvp, SinFromABoxKeepsItsCorners) {
  auto td = TDomain::create(0.0, 5.0, 1.0);
  Tube x(td);
  x.set_gate(0, Interval(0.5, 1.5));
  ASSERT_TRUE(CtcIvp(Function({"x"}, "-sin(x)")).contract(x));
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
    const Interval t(td->t(k));
    // Monotone flow: the exact gate is [flow(0.5), flow(1.5)]; the mean-value
    // form over a box this wide overestimates it a few times, no more.
    EXPECT_TRUE(x.gate(k).intersects(sin_flow(0.5, t))) << k;
    EXPECT_TRUE(x.gate(k).intersects(sin_flow(1.5, t))) << k;
    EXPECT_LT(x.gate(k).diam(), 5.0 * (sin_flow(1.5, t).ub() - sin_flow(0.5, t).lb()) + 1e-12) << k;
  }
}

TEST(CtcIvp, InconsistentGateEmptiesTheTube) {
  auto td = TDomain::create(0.0, 2.0, 0.5);
  Tube x(td);
  x.set_gate(0, Interval(1.0));
  x.set_gate(2, Interval(3.0, 4.0));
  EXPECT_FALSE(CtcIvp(Function({"x"}, "-sin(x)")).contract(x));
  EXPECT_TRUE(x.is_empty());
}

// The harmonic oscillator over 100 periods: test_ctc_ivp_mpfr.cpp (exact containment).

TEST(CtcIvp, LinearSystemFromABox) {
  // x' = A x, A = [[-1, 2], [-2, -1]]: x(t) = e^{-t} R(-2t) x0, a rotation that
  // contracts; the corners of the initial box are true trajectories.
  auto td = TDomain::create(0.0, 4.0, 0.25);
  TubeVector x(td, 2);
  x.set_gate(0, IntervalVector{Interval(0.9, 1.1), Interval(-0.1, 0.1)});
  ASSERT_TRUE(CtcIvp(Function({"x1", "x2"}, "(-x1 + 2*x2, -2*x1 - x2)")).contract(x));
  for (double a : {0.9, 1.1}) {
    for (double b : {-0.1, 0.1}) {
      for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
        const Interval t(td->t(k)), e = exp(-t), c = cos(Interval(2.0) * t), s = sin(Interval(2.0) * t);
        EXPECT_TRUE(x.gate(k)[0].intersects(e * (Interval(a) * c + Interval(b) * s))) << k;
        EXPECT_TRUE(x.gate(k)[1].intersects(e * (Interval(b) * c - Interval(a) * s))) << k;
      }
    }
  }
  // The image of the box is a rotated square of side 0.2 e^{-t}: its hull
  // at most sqrt(2) times wider, with QR wrapping not much more.
  const double w = 0.2 * std::exp(-4.0) * std::sqrt(2.0);
  EXPECT_LT(x.gate(td->nb_slices()).max_diam(), 1.2 * w);
}

TEST(CtcIvp, LorenzShortHorizonKeepsSampledTrajectories) {
  auto td = TDomain::create(0.0, 2.0, 0.1);
  TubeVector x(td, 3);
  const double r = 1e-6;
  x.set_gate(0, IntervalVector{Interval(15.0 - r, 15.0 + r), Interval(15.0 - r, 15.0 + r), Interval(36.0 - r, 36.0 + r)});
  ASSERT_TRUE(CtcIvp(Function({"x", "y", "z"}, "(10*(y - x), x*(28 - z) - y, x*y - 8/3*z)")).contract(x));
  const std::function<State<3>(const State<3>&)> f = [](const State<3>& s) {
    return State<3>{10 * (s[1] - s[0]), s[0] * (28 - s[2]) - s[1], s[0] * s[1] - 8.0L / 3 * s[2]};
  };
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-r, r);
  for (int sample = 0; sample < 6; ++sample) {
    State<3> s0{15.0L + u(rng), 15.0L + u(rng), 36.0L + u(rng)};
    for (std::size_t k : {5u, 10u, 20u}) {
      const State<3> s = rk4<3>(f, s0, td->t(k), 4000 * static_cast<int>(k));
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(x.gate(k)[i].inflate(1e-9).contains(static_cast<double>(s[i]))) << k << " " << i;
      }
    }
  }
  EXPECT_LT(x.gate(20).max_diam(), 1e-2);
}

TEST(CtcIvp, VanDerPolKeepsSampledTrajectories) {
  auto td = TDomain::create(0.0, 6.0, 0.5);
  TubeVector x(td, 2);
  const double r = 1e-3;
  x.set_gate(0, IntervalVector{Interval(2.0 - r, 2.0 + r), Interval(-r, r)});
  ASSERT_TRUE(CtcIvp(Function({"x1", "x2"}, "(x2, (1 - x1^2)*x2 - x1)")).contract(x));
  const std::function<State<2>(const State<2>&)> f = [](const State<2>& s) {
    return State<2>{s[1], (1 - s[0] * s[0]) * s[1] - s[0]};
  };
  for (double a : {-r, r}) {
    for (double b : {-r, 0.0, r}) {
      for (std::size_t k = 1; k <= td->nb_slices(); k += 3) {
        const State<2> s = rk4<2>(f, State<2>{2.0L + a, b}, td->t(k), 4000 * static_cast<int>(k));
        EXPECT_TRUE(x.gate(k)[0].inflate(1e-9).contains(static_cast<double>(s[0]))) << k;
        EXPECT_TRUE(x.gate(k)[1].inflate(1e-9).contains(static_cast<double>(s[1]))) << k;
      }
    }
  }
  EXPECT_LT(x.gate(td->nb_slices()).max_diam(), 0.05);
}

TEST(CtcIvp, OnlyContractsWhatIsKnown) {
  // A tube already tighter than the flow somewhere: never widened.
  auto td = TDomain::create(0.0, 2.0, 0.5);
  Tube x(td, Interval(-10.0, 10.0));
  x.set_gate(0, Interval(0.9, 1.1));
  x.set(Interval(0.0, 0.95), 2);
  const Tube before = x;
  ASSERT_TRUE(CtcIvp(Function({"x"}, "-sin(x)")).contract(x));
  EXPECT_TRUE(x.is_subset(before));
}

TEST(CtcIvp, ArgumentErrors) {
  EXPECT_THROW(CtcIvp(Function({"x", "u"}, "u"), 0), DimensionError);
  EXPECT_THROW(CtcIvp(Function({"x"}, "x"), 0, 0), Error);
  auto td = TDomain::create(0.0, 1.0, 0.5);
  TubeVector x(td, 2);
  Tube y(td);
  EXPECT_THROW(CtcIvp(Function({"x"}, "-x")).contract(x), DimensionError);
  EXPECT_THROW(CtcIvp(Function({"x", "u"}, "u"), 1).contract(y), DimensionError);
}

namespace {

// The contractor laws on x1' = x2, x2' = -x1 around x1 = a sin(t + p),
// x2 = a cos(t + p), tubes of random slicing and width.
::testing::AssertionResult rotation_laws_hold(const CtcIvp& ctc) {
  const auto gen = [](std::mt19937_64& rng) {
    std::uniform_real_distribution<double> ua(0.3, 2.0), up(-3.0, 3.0);
    const double a = ua(rng), p = up(rng);
    const kit::Trajectory1 s = [a, p](const Interval& t) { return Interval(a) * sin(t + Interval(p)); };
    const kit::Trajectory1 c = [a, p](const Interval& t) { return Interval(a) * cos(t + Interval(p)); };
    const auto td = kit::random_tdomain(rng, 12);
    kit::Case k;
    k.domains = {TubeVector({kit::tube_around(td, s, rng, 0.2, 0.6), kit::tube_around(td, c, rng, 0.2, 0.6)})};
    k.truth = {std::vector<kit::Trajectory1>{s, c}};
    return k;
  };
  const auto contract = [&ctc](kit::Domains& d) { ctc.contract(std::get<TubeVector>(d[0])); };
  kit::Options o;
  o.cases = 15;
  o.idempotence = kit::Idempotence::ContractionOnly;
  return kit::check_laws(contract, gen, o);
}

}  // namespace

TEST(CtcIvp, Laws) { EXPECT_TRUE(rotation_laws_hold(CtcIvp(Function({"x1", "x2"}, "(x2, -x1)"), 0, 12))); }

TEST(CtcIvp, LawsWithPieces) {
  CtcIvp ctc(Function({"x1", "x2"}, "(x2, -x1)"), 0, 12);
  ctc.set_max_pieces(8);
  EXPECT_TRUE(rotation_laws_hold(ctc));
}

TEST(CtcIvp, BoundedInputCoversTheExtremeInputs) {
  // x' = -x + u, u(t) ∈ [-0.1, 0.1], x(0) = 1: x(t) ∈ e^{-t} ± 0.1 (1 - e^{-t}),
  // both bounds reached by constant inputs; backward from x(3) too.
  auto td = TDomain::create(0.0, 3.0, 0.25);
  Tube x(td);
  x.set_gate(0, Interval(1.0));
  const Tube u(td, Interval(-0.1, 0.1));
  const CtcIvp ctc(Function({"x", "u"}, "-x + u"), 1);
  ASSERT_TRUE(ctc.contract(x, u));
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
    const Interval e = exp(-Interval(td->t(k)));
    const Interval lo = e - Interval(0.1) * (Interval(1.0) - e), hi = e + Interval(0.1) * (Interval(1.0) - e);
    EXPECT_TRUE(x.gate(k).intersects(lo) && x.gate(k).intersects(hi)) << k;
    EXPECT_LT(x.gate(k).diam(), 1.5 * (hi - lo).ub() + 1e-9) << k;
  }
}

TEST(CtcIvp, CausalChainKeepsExtremeTrajectories) {
  // A chain x1' = -x1 + u, x2' = x1 - x2 (thesis 4.4.1 in spirit), u ∈ [0.9, 1.1],
  // x(0) = (0, 0): the constant inputs 0.9 and 1.1 give the extreme
  // trajectories x1 = u(1 - e^{-t}), x2 = u(1 - e^{-t} - t e^{-t}).
  auto td = TDomain::create(0.0, 5.0, 0.5);
  TubeVector x(td, 2);
  x.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
  const TubeVector u(td, 1, Interval(0.9, 1.1));
  ASSERT_TRUE(CtcIvp(Function({"x1", "x2", "u"}, "(-x1 + u, x1 - x2)"), 1).contract(x, u));
  for (double a : {0.9, 1.1}) {
    for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
      const Interval t(td->t(k)), e = exp(-t);
      EXPECT_TRUE(x.gate(k)[0].intersects(Interval(a) * (Interval(1.0) - e))) << k;
      EXPECT_TRUE(x.gate(k)[1].intersects(Interval(a) * (Interval(1.0) - e - t * e))) << k;
    }
  }
  EXPECT_LT(x.gate(td->nb_slices())[0].diam(), 0.4);
}

namespace {

// Dead reckoning (thesis 3.4): the known part of the inputs in f through a
// time state τ, the noise n ∈ [-1/1000, 1/1000]² as input tubes.
const char* kDeadReckoning = "(x4*cos(x3), x4*sin(x3), -9/20*cos(tau/5) + n1, 1/10 + sin(tau/4) + n2, 1)";

State<5> dead_reckoning_rhs(const State<5>& s, long double c1, long double c2) {
  return State<5>{s[3] * std::cos(s[2]), s[3] * std::sin(s[2]), -9.0L / 20 * std::cos(s[4] / 5) + c1,
                  0.1L + std::sin(s[4] / 4) + c2, 1};
}

}  // namespace

TEST(CtcIvp, DeadReckoningKeepsExtremeTrajectoriesAndBeatsTheSliceBound) {
  const auto td = TDomain::create(0.0, 64.0, 0.5);
  const Interval noise = Interval(-1, 1) / Interval(1000);
  const TubeVector u(td, 2, noise);
  const CtcIvp ctc(Function({"x1", "x2", "x3", "x4", "tau", "n1", "n2"}, kDeadReckoning), 2, 10,
                   TimePropag::FORWARD);
  const Interval c = Interval(-1, 1) / Interval(100);
  TubeVector x(td, 5);
  x.set_gate(0, IntervalVector{Interval(-1, 1), Interval(-1, 1), Interval::half_pi() + c, c, Interval(0.0)});
  ASSERT_TRUE(ctc.contract(x, u));
  // Corners of the initial box with constant extreme inputs: true trajectories.
  for (double a : {-1.0, 1.0}) {
    for (double e : {-0.01, 0.01}) {
      for (double n : {-0.001, 0.001}) {
        const long double n1 = n, n2 = -n;
        const std::function<State<5>(const State<5>&)> f = [n1, n2](const State<5>& s) {
          return dead_reckoning_rhs(s, n1, n2);
        };
        State<5> s{a, -a, M_PI / 2 + e, e, 0};
        for (std::size_t k = 16; k <= td->nb_slices(); k += 16) {
          s = rk4<5>(f, s, 8.0L, 2000);
          for (std::size_t i = 0; i < 4; ++i) {
            EXPECT_TRUE(x.gate(k)[i].inflate(1e-9).contains(static_cast<double>(s[i]))) << k << " " << i;
          }
        }
      }
    }
  }
  // CtcDeriv on the same data ends in [23.01, 53.80] x [33.69, 72.21]
  // (examples/cpp/dead_reckoning.cpp, δ = 0.001); the sampled hull is
  // about 8.9 x 6.1.
  const IntervalVector end = x.gate(td->nb_slices());
  EXPECT_LT(end[0].diam(), 13.0) << end;
  EXPECT_LT(end[1].diam(), 13.0) << end;
}

TEST(CtcIvp, PointStartWithBoundedInputs) {
  // A point initial state and a noisy input: the a priori enclosure must
  // still be found (it once never settled from a degenerate box).
  const auto td = TDomain::create(0.0, 8.0, 0.5);
  const TubeVector u(td, 2, Interval(-1, 1) / Interval(1000));
  const CtcIvp ctc(Function({"x1", "x2", "x3", "x4", "tau", "n1", "n2"}, kDeadReckoning), 2, 10,
                   TimePropag::FORWARD);
  TubeVector x(td, 5);
  x.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0), Interval::half_pi(), Interval(0.0), Interval(0.0)});
  ASSERT_TRUE(ctc.contract(x, u));
  const IntervalVector end = x.gate(td->nb_slices());
  EXPECT_FALSE(end.is_unbounded()) << end;
  // The heading integrates the noise exactly: width 2 · 8 / 1000 (plus rounding).
  EXPECT_LT(end[2].diam(), 0.0161) << end;
  EXPECT_GT(end[2].diam(), 0.0159) << end;
}

// The memory of the network node (ivp_memory.h): a second run resumes at
// the first change and stays sound; a tube changed behind its back (even
// widened) is detected and integrated again in full.
TEST(CtcIvpMemory, ResumesAtTheChangeAndKeepsTheTruth) {
  auto td = TDomain::create(0.0, 10.0, 0.1);
  const CtcIvp ctc(Function({"x"}, "-sin(x)"));
  TubeVector x(td, 1);
  x.set_gate(0, IntervalVector{Interval(0.5, 1.5)});
  detail::IvpMemory memory;
  ASSERT_TRUE(ctc.contract(x, nullptr, memory));
  const std::size_t N = td->nb_slices(), k_obs = 80;
  // An observation at t = 8 of the trajectory from x0 = 1.2.
  x[0].set_gate(k_obs, x.gate(k_obs)[0] & sin_flow(1.2, Interval(td->t(k_obs))).inflate(1e-6));
  const TubeVector before = x;
  EXPECT_EQ(memory.first_change(x, nullptr, 1.0), k_obs);
  EXPECT_EQ(memory.first_change(x, nullptr, -1.0), N - k_obs);
  TubeVector full = x;
  ASSERT_TRUE(ctc.contract(x, nullptr, memory));
  ASSERT_TRUE(ctc.contract(full));
  EXPECT_TRUE(x.is_subset(before));
  for (std::size_t k = 0; k <= N; ++k) {
    EXPECT_TRUE(x.gate(k)[0].contains(sin_flow(1.2, Interval(td->t(k))).mid())) << k;
    // As tight as the full integration, up to the wrapping of the older sets.
    EXPECT_LT(x.gate(k)[0].diam(), 2.0 * full.gate(k)[0].diam() + 1e-12) << k;
  }
  EXPECT_LT(x.gate(0)[0].diam(), 1e-2);  // the observation reached back to t = 0 (width 1 before)
  // Nothing changed: nothing to do, nothing changes.
  EXPECT_EQ(memory.first_change(x, nullptr, 1.0), N + 1);
  const TubeVector same = x;
  ASSERT_TRUE(ctc.contract(x, nullptr, memory));
  EXPECT_TRUE(x == same);
}

TEST(CtcIvpMemory, AWidenedTubeIsIntegratedAgainInFull) {
  auto td = TDomain::create(0.0, 4.0, 0.25);
  const CtcIvp ctc(Function({"x"}, "-sin(x)"));
  TubeVector x(td, 1);
  x.set_gate(0, IntervalVector{Interval(1.0)});
  detail::IvpMemory memory;
  ASSERT_TRUE(ctc.contract(x, nullptr, memory));
  // The user starts again from another initial state on the same TDomain.
  TubeVector y(td, 1);
  y.set_gate(0, IntervalVector{Interval(2.0)});
  TubeVector fresh = y;
  EXPECT_EQ(memory.first_change(y, nullptr, 1.0), 0u);
  ASSERT_TRUE(ctc.contract(y, nullptr, memory));
  ASSERT_TRUE(ctc.contract(fresh));
  EXPECT_TRUE(y == fresh);
  // Another TDomain (refined): no reuse either.
  auto td2 = TDomain::create(0.0, 4.0, 0.125);
  TubeVector z(td2, 1);
  z.set_gate(0, IntervalVector{Interval(2.0)});
  EXPECT_EQ(memory.first_change(z, nullptr, 1.0), 0u);
}

TEST(CtcIvpMemory, InputChangesCount) {
  auto td = TDomain::create(0.0, 3.0, 0.25);
  const CtcIvp ctc(Function({"x", "u"}, "-x + u"), 1);
  TubeVector x(td, 1), u(td, 1, Interval(-0.1, 0.1));
  x.set_gate(0, IntervalVector{Interval(1.0)});
  detail::IvpMemory memory;
  ASSERT_TRUE(ctc.contract(x, &u, memory));
  u[0].set(Interval(0.0, 0.1), 5);  // the input known better on slice 5
  EXPECT_EQ(memory.first_change(x, &u, 1.0), 5u);
  const TubeVector before = x;
  ASSERT_TRUE(ctc.contract(x, &u, memory));
  EXPECT_TRUE(x.is_subset(before));
  EXPECT_LT(x.gate(td->nb_slices())[0].diam(), before.gate(td->nb_slices())[0].diam());
}
