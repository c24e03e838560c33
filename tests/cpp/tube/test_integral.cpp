// Integrals (3.7)-(3.9) and the primitive tube: hand-computed values, rigor
// against exact integrals (MPFR) of random trajectories inside random tubes.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "sillage/error.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_integral.h"

namespace sillage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();

// Slices [1,2], [-1,3], [0,0.5], [2,4] on [0,4]: L = 0,1,0,0,2 and U = 0,2,5,5.5,9.5 at t = 0..4.
Tube small_tube() {
  return Tube(TDomain::create(0, 4, 1), std::vector<Interval>{{1, 2}, {-1, 3}, {0, 0.5}, {2, 4}});
}

TEST(TubeIntegral, HandComputedSmallTube) {
  const Tube x = small_tube();
  EXPECT_EQ(integral(x, 4.0), Interval(2, 9.5));
  EXPECT_EQ(integral(x, 0.0), Interval(0, 0));
  EXPECT_EQ(integral(x, 2.5), Interval(0, 5.25));   // L = 0 + 0.5*0, U = 5 + 0.5*0.5
  EXPECT_EQ(integral(x, 1.5), Interval(0.5, 3.5));  // L = 1 - 0.5, U = 2 + 1.5
  EXPECT_EQ(integral(x, Interval(1, 3)), Interval(0, 5.5));
  EXPECT_EQ(integral(x, 1.0, 3.0), Interval(-1, 3.5));
  // L([0.5,1.5]) = [0.5,1], L([2.5,4]) = [0,2], U([0.5,1.5]) = [1,3.5], U([2.5,4]) = [5.25,9.5].
  const auto [lo, up] = partial_integral(x, Interval(0.5, 1.5), Interval(2.5, 4));
  EXPECT_EQ(lo, Interval(-1, 1.5));
  EXPECT_EQ(up, Interval(1.75, 8.5));
  EXPECT_EQ(integral(x, Interval(0.5, 1.5), Interval(2.5, 4)), Interval(-1, 8.5));
  // Reversed bounds: ∫_3^1 = -∫_1^3 ∈ [-3.5, 1].
  EXPECT_EQ(integral(x, 3.0, 1.0), Interval(-3.5, 1));
  // Crossing bounds: t1 = 4, t2 = 0 gives -∫_0^4 x down to -9.5.
  EXPECT_EQ(integral(x, Interval(0, 4), Interval(0, 4)), Interval(-9.5, 9.5));
  // The analysis object answers the same.
  const TubeAnalysis a(x);
  EXPECT_EQ(a.integral(4.0), Interval(2, 9.5));
  EXPECT_EQ(a.integral(Interval(0.5, 1.5), Interval(2.5, 4)), Interval(-1, 8.5));
  EXPECT_EQ(a.eval(Interval(0.5, 1.5)), x(Interval(0.5, 1.5)));
}

TEST(TubeIntegral, UnboundedSlices) {
  // [1,1], [-inf,1], [1,1], [1,1] on [0,4].
  const Tube x(TDomain::create(0, 4, 1), std::vector<Interval>{{1, 1}, {-kInf, 1}, {1, 1}, {1, 1}});
  EXPECT_EQ(integral(x, 2.0, 4.0), Interval(2, 2));  // past the unbounded slice: finite
  EXPECT_EQ(integral(x, 0.0, 4.0), Interval(-kInf, 4));
  EXPECT_EQ(integral(x, 1.0), Interval(1, 1));
  EXPECT_EQ(integral(x, 1.5), Interval(-kInf, 1.5));
  // Both ends inside the same unbounded slice: still -inf between them.
  EXPECT_EQ(integral(x, 1.25, 1.75), Interval(-kInf, 0.5));
  EXPECT_EQ(integral(x, 1.75, 1.25), Interval(-0.5, kInf));
  EXPECT_EQ(integral(x, 1.5, 1.5), Interval(0, 0));
  const auto [lo, up] = partial_integral(x, Interval(0.5, 2.5), Interval(3, 4));
  EXPECT_EQ(lo, Interval(-kInf, 2));  // max: ∫_2^4 1
  EXPECT_EQ(up, Interval(0.5, 3.5));
  EXPECT_EQ(integral(x, Interval(0.5, 2.5), Interval(3, 4)), Interval(-kInf, 3.5));
  // Reversed across the unbounded slice: -∫_{0.5}^{3} x^- = +inf for every pair.
  const auto [rlo, rup] = partial_integral(x, Interval(3), Interval(0.5));
  EXPECT_EQ(rlo, Interval(kMax, kInf));
  EXPECT_EQ(rup, Interval(-2.5));
  EXPECT_EQ(integral(x, 3.0, 0.5), Interval(-2.5, kInf));
  const Tube y(TDomain::create(0, 3, 1), std::vector<Interval>{{0, 1}, {0, kInf}, {0, 1}});
  EXPECT_EQ(integral(y, 3.0), Interval(0, kInf));
  EXPECT_EQ(integral(y, 2.0, 3.0), Interval(0, 1));
  EXPECT_EQ(integral(y, Interval(0, 1.5), Interval(2, 3)), Interval(0, kInf));
}

TEST(TubeIntegral, EmptyAndInvalid) {
  const Tube x = small_tube();
  EXPECT_TRUE(integral(x, Interval::empty()).is_empty());
  EXPECT_TRUE(integral(x, Interval::empty(), Interval(1, 2)).is_empty());
  EXPECT_THROW(integral(x, 5.0), Error);
  EXPECT_THROW(integral(x, -0.5, 1.0), Error);
  EXPECT_THROW(integral(x, std::nan(""), 1.0), Error);
  EXPECT_THROW(integral(x, Interval(3, 5)), Error);
  EXPECT_THROW(partial_integral(x, Interval(-1, 1), Interval(2, 3)), Error);
  Tube e = small_tube();
  e.set(Interval::empty(), 2);
  EXPECT_TRUE(integral(e, 1.0).is_empty());
  EXPECT_TRUE(partial_integral(e, Interval(0), Interval(1)).first.is_empty());
  EXPECT_TRUE(primitive(e).is_empty());
  EXPECT_TRUE(primitive(x, Interval::empty()).is_empty());
}

TEST(TubeIntegral, AnalysisRebuildsWhenTheTubeChanges) {
  Tube x = small_tube();
  const TubeAnalysis a(x);
  EXPECT_EQ(a.integral(4.0), Interval(2, 9.5));
  const auto before = a.tree();
  EXPECT_EQ(a.tree(), before);  // unchanged tube: same tree
  x.set(Interval(0, 1), 3);
  EXPECT_EQ(a.integral(4.0), Interval(0, 6.5));
  x.tdomain()->sample(0.5);
  EXPECT_EQ(a.tree()->nb_slices(), 5u);
  EXPECT_EQ(a.integral(4.0), Interval(0, 6.5));
  x = Tube(TDomain::create(0, 1, 0.5), Interval(1, 2));
  EXPECT_EQ(a.integral(1.0), Interval(1, 2));
}

// ---- rigor: exact integrals of random trajectories with MPFR ----

class Exact {
 public:
  Exact() { mpfr_init2(v_, 4200); mpfr_set_zero(v_, 1); }  // enough bits: sums of products of doubles are exact
  ~Exact() { mpfr_clear(v_); }
  Exact(const Exact&) = delete;
  Exact& operator=(const Exact&) = delete;
  // v += (b - a) * c, exactly.
  void add(double a, double b, double c) {
    mpfr_t d;
    mpfr_init2(d, 4200);
    mpfr_set_d(d, b, MPFR_RNDN);
    mpfr_sub_d(d, d, a, MPFR_RNDN);
    mpfr_mul_d(d, d, c, MPFR_RNDN);
    mpfr_add(v_, v_, d, MPFR_RNDN);
    mpfr_clear(d);
  }
  void negate() { mpfr_neg(v_, v_, MPFR_RNDN); }
  bool in(const Interval& x) const {
    return !x.is_empty() && mpfr_cmp_d(v_, x.lb()) >= 0 && mpfr_cmp_d(v_, x.ub()) <= 0;
  }
  double approx() const { return mpfr_get_d(v_, MPFR_RNDN); }

 private:
  mpfr_t v_;
};

// Piecewise-constant trajectory: value c_k[j] on the j-th of two pieces of slice k.
struct Piecewise {
  std::vector<double> cut;             // split point inside each slice
  std::vector<std::array<double, 2>> c;
};

// ∫_{s1}^{s2} of the trajectory (f = the trajectory, or its lower/upper bound functions).
void exact_integral(Exact& out, const std::vector<double>& ts, const Piecewise& p, double s1, double s2) {
  const bool rev = s1 > s2;
  if (rev) std::swap(s1, s2);
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const double pieces[3] = {ts[k], p.cut[k], ts[k + 1]};
    for (int j = 0; j < 2; ++j) {
      const double a = std::max(s1, pieces[j]), b = std::min(s2, pieces[j + 1]);
      if (a < b) out.add(a, b, p.c[k][static_cast<std::size_t>(j)]);
    }
  }
  if (rev) out.negate();
}

TEST(TubeIntegral, RandomTrajectoriesHaveTheirExactIntegralInside) {
  std::mt19937_64 rng(2017);
  std::uniform_real_distribution<double> u(-5, 5), p(0, 1);
  int checks = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial) * 7;
    const auto td = trial % 2 ? TDomain::create(-1.3, -1.3 + 0.1 * static_cast<double>(n), 0.1)
                              : TDomain::create(0.7, 0.7 + 0.37 * static_cast<double>(n), 0.37);
    const std::size_t m = td->nb_slices();
    const auto ts = std::vector<double>(td->times().begin(), td->times().end());
    std::vector<Interval> slices;
    Piecewise traj, lo, hi;
    for (std::size_t k = 0; k < m; ++k) {
      double a = u(rng), b = u(rng);
      if (a > b) std::swap(a, b);
      slices.emplace_back(a, b);
      const double cut = ts[k] + p(rng) * (ts[k + 1] - ts[k]);
      for (Piecewise* q : {&traj, &lo, &hi}) q->cut.push_back(cut);
      traj.c.push_back({a + p(rng) * (b - a), a + p(rng) * (b - a)});
      traj.c.back()[0] = std::clamp(traj.c.back()[0], a, b);
      traj.c.back()[1] = std::clamp(traj.c.back()[1], a, b);
      // Every fourth tube has some unbounded slices (the trajectory stays finite).
      if (trial % 4 == 3 && p(rng) < 0.15) a = -kInf;
      if (trial % 4 == 3 && p(rng) < 0.15) b = kInf;
      slices.back() = Interval(a, b);
      lo.c.push_back({a, a});
      hi.c.push_back({b, b});
    }
    const Tube x(td, slices);
    const TubeAnalysis an(x);
    std::uniform_real_distribution<double> t(td->t0(), td->tf());
    for (int q = 0; q < 30; ++q) {
      double a1 = t(rng), b1 = t(rng), a2 = t(rng), b2 = t(rng);
      if (q % 3 == 0) {  // ordered bounds: a1 <= b1 <= a2 <= b2
        double v[4] = {a1, b1, a2, b2};
        std::sort(v, v + 4);
        a1 = v[0], b1 = v[1], a2 = v[2], b2 = v[3];
      }
      if (a1 > b1) std::swap(a1, b1);
      if (a2 > b2) std::swap(a2, b2);
      const Interval t1(a1, b1), t2(a2, b2);
      const Interval whole = an.integral(t1, t2);
      const auto [plo, pup] = an.partial_integral(t1, t2);
      for (int s = 0; s < 4; ++s) {
        const double s1 = a1 + p(rng) * (b1 - a1), s2 = a2 + p(rng) * (b2 - a2);
        const double c1 = std::clamp(s1, a1, b1), c2 = std::clamp(s2, a2, b2);
        Exact e, el, eh;
        exact_integral(e, ts, traj, c1, c2);
        exact_integral(el, ts, lo, c1, c2);
        exact_integral(eh, ts, hi, c1, c2);
        EXPECT_TRUE(e.in(whole)) << e.approx() << " not in " << whole;
        EXPECT_TRUE(e.in(an.integral(c1, c2))) << e.approx();
        EXPECT_TRUE(el.in(plo)) << el.approx() << " not in " << plo;
        EXPECT_TRUE(eh.in(pup)) << eh.approx() << " not in " << pup;
        Exact from0;
        exact_integral(from0, ts, traj, td->t0(), c2);
        EXPECT_TRUE(from0.in(an.integral(c2)));
        EXPECT_TRUE(from0.in(an.integral(t2)));
        ++checks;
      }
      // Tightness: the bound-function integrals are reached up to rounding.
      const double from = std::min(a1, b2), to = std::max(a1, b2);
      Exact el, eh;
      exact_integral(el, ts, lo, from, to);
      exact_integral(eh, ts, hi, from, to);
      const Interval point = an.integral(from, to);
      EXPECT_LE(point.lb(), el.approx());
      EXPECT_GE(point.ub(), eh.approx());
      if (std::isfinite(el.approx())) EXPECT_NEAR(point.lb(), el.approx(), 1e-9 * (1 + std::fabs(el.approx())));
      else EXPECT_EQ(point.lb(), -kInf);
      if (std::isfinite(eh.approx())) EXPECT_NEAR(point.ub(), eh.approx(), 1e-9 * (1 + std::fabs(eh.approx())));
      else EXPECT_EQ(point.ub(), kInf);
    }
  }
  EXPECT_GT(checks, 4000);
}

// Many unbounded slices, bounds on time points, degenerate and crossing
// [t1], [t2]: every pair (s1, s2), the ends of the boxes included, has its
// exact integrals (possibly infinite) inside.
TEST(TubeIntegral, UnboundedSlicesAgainstExactPairs) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-5, 5), p(0, 1);
  for (int trial = 0; trial < 3000; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial % 7);
    const auto td = TDomain::create(0, static_cast<double>(n), 1);
    const auto ts = std::vector<double>(td->times().begin(), td->times().end());
    std::vector<Interval> slices;
    Piecewise traj, lo, hi;
    for (std::size_t k = 0; k < n; ++k) {
      double a = u(rng), b = u(rng);
      if (a > b) std::swap(a, b);
      const double c = std::clamp(a + p(rng) * (b - a), a, b);
      if (p(rng) < 0.3) a = -kInf;
      if (p(rng) < 0.3) b = kInf;
      slices.emplace_back(a, b);
      for (Piecewise* q : {&traj, &lo, &hi}) q->cut.push_back(static_cast<double>(k) + 0.5);
      traj.c.push_back({c, c});
      lo.c.push_back({a, a});
      hi.c.push_back({b, b});
    }
    const SynthesisTree tree(ts, slices);
    auto random_t = [&] {
      double a = p(rng) * static_cast<double>(n), b = p(rng) * static_cast<double>(n);
      if (p(rng) < 0.2) a = std::floor(a);
      if (p(rng) < 0.2) b = a;
      if (a > b) std::swap(a, b);
      return Interval(a, b);
    };
    const Interval t1 = random_t(), t2 = random_t();
    const Interval whole = integral(tree, t1, t2);
    const auto [plo, pup] = partial_integral(tree, t1, t2);
    for (int q = 0; q < 6; ++q) {
      double s1 = std::clamp(t1.lb() + p(rng) * t1.diam(), t1.lb(), t1.ub());
      double s2 = std::clamp(t2.lb() + p(rng) * t2.diam(), t2.lb(), t2.ub());
      if (q == 0) s1 = t1.lb(), s2 = t2.ub();
      if (q == 1) s1 = t1.ub(), s2 = t2.lb();
      Exact e, el, eh;
      exact_integral(e, ts, traj, s1, s2);
      exact_integral(el, ts, lo, s1, s2);
      exact_integral(eh, ts, hi, s1, s2);
      ASSERT_TRUE(e.in(whole)) << t1 << " " << t2 << " " << s1 << " " << s2;
      ASSERT_TRUE(e.in(integral(tree, s1, s2))) << s1 << " " << s2;
      ASSERT_TRUE(el.in(plo)) << el.approx() << " not in " << plo;
      ASSERT_TRUE(eh.in(pup)) << eh.approx() << " not in " << pup;
    }
  }
}

TEST(TubeIntegral, PrimitiveOfKnownDerivativeContainsTheExactPrimitive) {
  const auto td = TDomain::create(0, 3, 0.01);
  const Tube v(td, "2*t");  // p(t) = 1 + t^2
  const Tube p = primitive(v, Interval(1.0));
  EXPECT_EQ(p.gate(0), Interval(1.0));
  EXPECT_TRUE(p.contains(Trajectory("1 + t^2", td->t0_tf())));
  const Tube w(td, "cos(t) + [-0.01, 0.01]");
  const Tube q = primitive(w, Interval(-0.5, 0.5));
  EXPECT_TRUE(q.contains(Trajectory("sin(t)", td->t0_tf())));
  EXPECT_TRUE(q.contains(Trajectory("sin(t) + 0.5 - 0.01*t", td->t0_tf())));
  // Hand-computed on the small tube: gates = 0 + L..U, slices = hull of the cones.
  const Tube x = small_tube();
  const Tube r = primitive(x);
  const Interval gates[] = {{0, 0}, {1, 2}, {0, 5}, {0, 5.5}, {2, 9.5}};
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(r.gate(k), gates[k]) << k;
  EXPECT_EQ(r.slice(0), Interval(0, 2));
  EXPECT_EQ(r.slice(1), Interval(0, 5));    // [1,2] + [0,1]*[-1,3]
  EXPECT_EQ(r.slice(2), Interval(0, 5.5));  // [0,5] + [0,1]*[0,0.5]
  EXPECT_EQ(r.slice(3), Interval(0, 9.5));
  // Consistency with the integrals at time points.
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(r.gate(k), integral(x, static_cast<double>(k)));
}

// The cached tree answers long x([t]) queries and follows every modification.
TEST(TubeTreeCache, LongQueriesMatchTheScanAndFollowChanges) {
  auto td = std::make_shared<TDomain>(0.0, 10.0, 0.01);
  Tube x(td, "sin(t) + [-0.1, 0.1]");
  auto scan = [&](const Interval& t) {
    Interval r = Interval::empty();
    for (std::size_t k = 0; k < x.nb_slices(); ++k) {
      if (td->t(k) < t.ub() && td->t(k + 1) > t.lb()) r |= x.slice(k);
    }
    for (std::size_t k = 0; k <= x.nb_slices(); ++k) {
      if (t.contains(td->t(k))) r |= x.gate(k);
    }
    return r;
  };
  const Interval t(0.5, 9.5);
  EXPECT_EQ(x(t), scan(t));
  const auto first = x.synthesis_tree();
  EXPECT_EQ(x.synthesis_tree(), first);  // cached
  x.set(Interval(5, 6), 500);
  EXPECT_NE(x.synthesis_tree(), first);  // rebuilt after the change
  EXPECT_EQ(x(t), scan(t));
  EXPECT_EQ(x(t).ub(), 6);
  Tube y(x);  // a copy has a tree of its own
  y.set(Interval(7, 8), 100);
  EXPECT_EQ(x(t).ub(), 6);
  EXPECT_EQ(y(t).ub(), 8);
  td->sample(5.005);
  EXPECT_EQ(x(t), scan(t));
}

}  // namespace
}  // namespace sillage
