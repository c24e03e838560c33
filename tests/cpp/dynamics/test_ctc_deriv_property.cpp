// CtcDeriv on random tubes around a known trajectory (a sum of sines and its
// exact derivative, enclosed in interval arithmetic): the truth is never
// removed, results only shrink, one FWD_BWD call is a fixed point, both
// rounding policies agree bit for bit, and the result matches a brute-force
// evaluation of the definition (4.4) on a fine sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>

#include "deriv_test_util.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/interval/arith_rows.h"

using namespace sillage;
using sillage::test::BothRoundings;
using sillage::test::SineSum;

namespace {

const double kInf = rounding::kInf;

struct Problem {
  SineSum f;
  Tube x, v;
};

// Tubes around f: slices and gates inflated by [e_min, e_min + 0.3] on each
// side, some gates unknown (all reals), v inflated by [0, 0.5], sometimes
// unbounded on one side.
Problem make_problem(std::mt19937_64& rng, int n, double e_min) {
  SineSum f(rng);
  const auto td = sillage::test::random_tdomain(rng, n);
  std::uniform_real_distribution<double> e(e_min, e_min + 0.3), ev(0.0, 0.5), u(0, 1);
  std::vector<Interval> xs(td->nb_slices()), gs(td->nb_slices() + 1), vs(td->nb_slices());
  auto inflate = [&](const Interval& y) { return Interval(y.lb() - e(rng), y.ub() + e(rng)); };
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const Interval t = td->slice_domain(k);
    xs[k] = u(rng) < 0.2 ? Interval() : inflate(f.x(t));
    const Interval vt = f.v(t);
    const double r = u(rng);
    vs[k] = Interval(r < 0.05 ? -kInf : vt.lb() - ev(rng), r > 0.95 ? kInf : vt.ub() + ev(rng));
  }
  for (std::size_t k = 0; k < gs.size(); ++k) {
    gs[k] = u(rng) < 0.6 ? Interval() : inflate(f.x(Interval(td->t(k))));
  }
  // Outward rounding of the inflations: Interval(lb - e, ub + e) rounds to
  // nearest; widen by one ulp so that the truth stays strictly inside.
  for (auto* arr : {&xs, &gs}) {
    for (auto& y : *arr) {
      if (y.is_bounded()) y = Interval(rounding::next_down(y.lb()), rounding::next_up(y.ub()));
    }
  }
  return {f, Tube(td, xs, gs), Tube(td, vs)};
}

// The truth (enclosed by f.x at sampled times) is inside x: at every gate and
// at `samples` times per slice. strict: the enclosure is a subset; else it
// only meets the tube (for tubes that may be as thin as the enclosure).
::testing::AssertionResult contains_truth(const Tube& x, const SineSum& f, int samples, bool strict) {
  const auto& td = *x.tdomain();
  auto check = [&](const Interval& truth, const Interval& y, const char* what, std::size_t k, double t) {
    const bool ok = strict ? truth.is_subset(y) : truth.intersects(y);
    if (ok) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << what << " " << k << " at t = " << t << ": truth " << truth << " not in "
                                         << y;
  };
  for (std::size_t k = 0; k <= td.nb_slices(); ++k) {
    auto r = check(f.x(Interval(td.t(k))), x.gate(k), "gate", k, td.t(k));
    if (!r) return r;
  }
  for (std::size_t k = 0; k < td.nb_slices(); ++k) {
    for (int i = 0; i <= samples; ++i) {
      const double t = td.t(k) + (td.t(k + 1) - td.t(k)) * i / samples;
      if (t < td.t(k) || t > td.t(k + 1)) continue;
      auto r = check(f.x(Interval(t)), x.slice(k), "slice", k, t);
      if (!r) return r;
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace

class CtcDerivProperty : public BothRoundings {};
INSTANTIATE_TEST_SUITE_P(Rounding, CtcDerivProperty, ::testing::Bool(), sillage::test::rounding_name);

TEST_P(CtcDerivProperty, TruthKeptContractionOnlyFixedPoint) {
  std::mt19937_64 rng(2024);
  for (int trial = 0; trial < 300; ++trial) {
    Problem p = make_problem(rng, std::uniform_int_distribution<int>(1, 40)(rng), 1e-6);
    for (TimePropag mode : {TimePropag::FORWARD, TimePropag::BACKWARD, TimePropag::FWD_BWD}) {
      Tube x = p.x;
      ASSERT_TRUE(CtcDeriv(mode).contract(x, p.v)) << trial;
      ASSERT_TRUE(x.is_subset(p.x)) << trial;
      ASSERT_TRUE(contains_truth(x, p.f, 7, true)) << "trial " << trial << " mode " << static_cast<int>(mode);
      if (mode == TimePropag::FWD_BWD) {
        const Tube once = x;
        const auto version = x.version();
        ASSERT_TRUE(CtcDeriv().contract(x, p.v));
        ASSERT_EQ(x, once) << trial;
        ASSERT_EQ(x.version(), version) << trial;
        // Forward then backward alone, or the other way, gain nothing either.
        CtcDeriv(TimePropag::BACKWARD).contract(x, p.v);
        CtcDeriv(TimePropag::FORWARD).contract(x, p.v);
        ASSERT_EQ(x, once) << trial;
      }
    }
  }
}

TEST_P(CtcDerivProperty, ThinTubesNeverLoseTheTruth) {
  // No inflation at all on x: the tube is the natural enclosure itself.
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    Problem p = make_problem(rng, std::uniform_int_distribution<int>(1, 30)(rng), 0.0);
    Tube x = p.x;
    ASSERT_TRUE(CtcDeriv().contract(x, p.v)) << trial;
    ASSERT_TRUE(contains_truth(x, p.f, 5, false)) << trial;
  }
}

TEST_P(CtcDerivProperty, RestrictedRangeEqualsWholeOnThatRange) {
  // The range form reads and writes nothing outside, and over a range that
  // is the whole tube it is the plain form.
  std::mt19937_64 rng(99);
  for (int trial = 0; trial < 100; ++trial) {
    Problem p = make_problem(rng, 12, 1e-6);
    std::uniform_int_distribution<std::size_t> k(0, 11);
    std::size_t first = k(rng), last = k(rng);
    if (first > last) std::swap(first, last);
    Tube x = p.x;
    ASSERT_TRUE(CtcDeriv().contract(x, p.v, first, last));
    for (std::size_t j = 0; j < 12; ++j) {
      if (j < first || j > last) {
        ASSERT_EQ(x.slice(j), p.x.slice(j));
      }
    }
    for (std::size_t j = 0; j <= 12; ++j) {
      if (j < first || j > last + 1) {
        ASSERT_EQ(x.gate(j), p.x.gate(j));
      }
    }
    ASSERT_TRUE(contains_truth(x, p.f, 3, true));
    Tube y = p.x, z = p.x;
    CtcDeriv().contract(y, p.v, 0, 11);
    CtcDeriv().contract(z, p.v);
    ASSERT_EQ(y, z);
  }
}

namespace {

// CtcDeriv in every mode on random problems, on path 0 and on path 1 (use(p)
// selects path p): the same results, bit for bit, zero signs included. Up
// to 300 slices: the FWD_BWD hulls go by blocks of 64 slices and lanes of 4
// or 8, with partial blocks and lanes at the ends; ranges too.
template <class Use>
void check_paths_agree(unsigned seed, Use use) {
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = std::uniform_int_distribution<int>(1, trial % 3 ? 50 : 300)(rng);
    Problem p = make_problem(rng, n, trial % 2 ? 0.0 : 1e-3);
    std::uniform_int_distribution<std::size_t> k(0, static_cast<std::size_t>(n) - 1);
    std::size_t first = k(rng), last = k(rng);
    if (first > last) std::swap(first, last);
    for (TimePropag mode : {TimePropag::FORWARD, TimePropag::BACKWARD, TimePropag::FWD_BWD}) {
      Tube x[2] = {p.x, p.x}, xr[2] = {p.x, p.x};
      bool ok[2];
      for (int path = 0; path < 2; ++path) {
        use(path);
        ok[path] = CtcDeriv(mode).contract(x[path], p.v);
        CtcDeriv(mode).contract(xr[path], p.v, first, last);
      }
      ASSERT_EQ(ok[0], ok[1]) << trial;
      ASSERT_EQ(x[0], x[1]) << trial;
      ASSERT_EQ(xr[0], xr[1]) << trial;
      for (std::size_t j = 0; j < x[0].nb_slices(); ++j) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(x[0].slice(j).lb()), std::bit_cast<std::uint64_t>(x[1].slice(j).lb()))
            << trial << " slice " << j;
        ASSERT_EQ(std::bit_cast<std::uint64_t>(x[0].slice(j).ub()), std::bit_cast<std::uint64_t>(x[1].slice(j).ub()))
            << trial << " slice " << j;
      }
    }
  }
}

}  // namespace

TEST(CtcDerivRounding, HardwareAndSoftwareAgree) {
  if (!detail::hardware_rounding_available()) GTEST_SKIP() << "no hardware static rounding";
  const bool saved = detail::hardware_rounding();
  check_paths_agree(5, [](int path) { detail::set_hardware_rounding(path == 1); });
  detail::set_hardware_rounding(saved);
}

// The portable path with AVX2 (the FWD_BWD hulls 4 slices at a time,
// slice_rule_x4.h) against one slice at a time.
TEST(CtcDerivRounding, Avx2HullsAndScalarAgree) {
  if (!detail::avx2_rows_available()) GTEST_SKIP() << "no AVX2";
  const bool saved = detail::hardware_rounding();
  detail::set_hardware_rounding(false);
  check_paths_agree(11, [](int path) { detail::set_avx2_rows(path == 1); });
  detail::set_avx2_rows(true);
  detail::set_hardware_rounding(saved);
}

// ---- the definition (4.4), brute force ----

namespace {

// ∫_{t1}^{t2} [v] for the piecewise-constant [v] of the tube (t1 <= t2):
// sum over slices of (overlap length) · [v](k), in interval arithmetic.
Interval integral(const Tube& v, double t1, double t2) {
  const auto& td = *v.tdomain();
  Interval r(0.0);
  for (std::size_t k = 0; k < td.nb_slices(); ++k) {
    const double lo = std::max(t1, td.t(k)), hi = std::min(t2, td.t(k + 1));
    if (lo < hi) r += (Interval(hi) - Interval(lo)) * v.slice(k);
  }
  return r;
}

// [x](t): the gate at a time point, the slice elsewhere.
Interval value(const Tube& x, double t) { return x(t); }

}  // namespace

TEST_P(CtcDerivProperty, MatchesBruteForceDefinition) {
  // Small tubes, bounded derivatives: for sampled t, the reference is
  //   R(t) = ∩ over sampled t1 of ([x](t1) + ∫_{t1}^{t} [v])
  // (t1 over the time points and 100 points per slice). Ours contains the
  // truth (above) and, per slice, its hull matches the hull of R over the
  // slice up to the sampling error h·max|v| on each side.
  std::mt19937_64 rng(31);
  for (int trial = 0; trial < 40; ++trial) {
    SineSum f(rng);
    const auto td = sillage::test::random_tdomain(rng, 5);
    std::uniform_real_distribution<double> e(0.0, 0.4), u(0, 1);
    std::vector<Interval> xs(5), gs(6), vs(5);
    double vmax = 0;
    for (std::size_t k = 0; k < 5; ++k) {
      const Interval t = td->slice_domain(k);
      const Interval xt = f.x(t), vt = f.v(t);
      xs[k] = Interval(xt.lb() - 0.3 - e(rng), xt.ub() + 0.3 + e(rng));
      vs[k] = Interval(vt.lb() - e(rng), vt.ub() + e(rng));
      vmax = std::max(vmax, vs[k].mag());
    }
    for (std::size_t k = 0; k <= 5; ++k) {
      const Interval g = f.x(Interval(td->t(k)));
      gs[k] = u(rng) < 0.5 ? Interval() : Interval(g.lb() - e(rng), g.ub() + e(rng));
    }
    const Tube x0(td, xs, gs), v(td, vs);
    Tube x = x0;
    ASSERT_TRUE(CtcDeriv().contract(x, v));

    // Samples: every time point, 100 interior points per slice.
    const int m = 100;
    std::vector<double> ts;
    double h = 0;
    for (std::size_t k = 0; k < 5; ++k) {
      const double a = td->t(k), b = td->t(k + 1);
      h = std::max(h, (b - a) / m);
      for (int i = 0; i < m; ++i) ts.push_back(a + (b - a) * i / m);
    }
    ts.push_back(td->tf());
    auto reference = [&](double t) {
      Interval r = value(x0, t);
      for (double t1 : ts) {
        r &= t1 <= t ? value(x0, t1) + integral(v, t1, t) : value(x0, t1) - integral(v, t, t1);
      }
      return r;
    };
    const double tol = 2 * h * vmax + 1e-9;
    for (std::size_t k = 0; k <= 5; ++k) {
      const Interval ref = reference(td->t(k));
      ASSERT_FALSE(ref.is_empty());
      ASSERT_LE(std::abs(x.gate(k).lb() - ref.lb()), tol) << "gate " << k << " ours " << x.gate(k) << " ref " << ref;
      ASSERT_LE(std::abs(x.gate(k).ub() - ref.ub()), tol) << "gate " << k << " ours " << x.gate(k) << " ref " << ref;
    }
    for (std::size_t k = 0; k < 5; ++k) {
      Interval hull = Interval::empty();
      for (double t : ts) {
        if (t > td->t(k) && t < td->t(k + 1)) hull |= reference(t);
      }
      hull |= reference(td->t(k)) | reference(td->t(k + 1));
      ASSERT_LE(std::abs(x.slice(k).lb() - hull.lb()), tol) << "slice " << k << " ours " << x.slice(k) << " ref "
                                                            << hull;
      ASSERT_LE(std::abs(x.slice(k).ub() - hull.ub()), tol) << "slice " << k << " ours " << x.slice(k) << " ref "
                                                            << hull;
    }
  }
}
