// The interval Newton test N and the count of zeros (thesis Alg. 10 with
// Remark 6.1), and their comparison with the degree test T on near-parallel
// crossings (Fig. 6.19).
#include <gtest/gtest.h>

#include <random>

#include "plane_maps.h"
#include "sillage/loops/zero_tests.h"

using namespace sillage;
using namespace sillage::test;

namespace {

PlaneJacobian constant_jacobian(const IntervalMatrix& j) {
  return [j](const IntervalVector&) { return j; };
}

const PlaneFunction kIdentity = [](const IntervalVector& t) { return t; };
const PlaneJacobian kIdentityJacobian = constant_jacobian(IntervalMatrix::identity(2));

// z^2 - 1 = (x^2 - y^2 - 1, 2xy), zeros ±1, Jacobian [[2x, -2y], [2y, 2x]], det 4|z|^2.
const auto kZ2m1 = [](auto x, auto y) { return std::pair{sq(x) - sq(y) - 1.0, 2.0 * x * y}; };
const PlaneJacobian kZ2Jacobian = [](const IntervalVector& t) {
  return IntervalMatrix{{2.0 * t[0], -2.0 * t[1]}, {2.0 * t[1], 2.0 * t[0]}};
};

// The near-parallel crossing of Fig. 6.19b in a t-plane: the trajectory
// crosses itself at t = (0, 0) under an angle δ, positions known up to ±e and
// velocities up to ±δ. g(t1, t2) = p(t2) - p(t1) = (t2 - t1, δ t2).
struct NearParallel {
  double delta = 0.01, e = 0.001;
  PlaneFunction f() const {
    return [d = delta, e = e](const IntervalVector& t) {
      const Interval noise(-e, e);
      return IntervalVector{t[1] - t[0] + noise, d * t[1] + noise};
    };
  }
  PlaneJacobian jacobian() const {
    const Interval u(-delta, delta);
    return constant_jacobian(IntervalMatrix{{Interval(-1) + u, Interval(1) + u}, {u, delta + u}});
  }
  // A t-box holding the crossing: |t2| <= a with δ a > e, |t1| <= b with b > a + e.
  IntervalVector region() const { return box(-0.5, 0.5, -0.3, 0.3); }
};

}  // namespace

// ---- Newton ----

TEST(NewtonTest, ProvesASimpleZero) {
  // (x^2 + y^2 - 1, x - y): the zero (1/√2, 1/√2).
  const auto map = [](auto x, auto y) { return std::pair{sq(x) + sq(y) - 1.0, x - y}; };
  const PlaneJacobian j = [](const IntervalVector& t) {
    return IntervalMatrix{{2.0 * t[0], 2.0 * t[1]}, {Interval(1), Interval(-1)}};
  };
  const NewtonResult r = newton_test(box(0.6, 0.8, 0.6, 0.8), interval_map(map), j);
  EXPECT_TRUE(r.proven);
  const double z = std::sqrt(0.5);
  EXPECT_TRUE(r.box.contains({z, z})) << r.box;
  EXPECT_TRUE(r.box.is_subset(box(0.6, 0.8, 0.6, 0.8)));
  EXPECT_GE(r.nb_iterations, 1u);
}

TEST(NewtonTest, ContractsBeforeProving) {
  // (x + y^2/2 - 0.3, y + x^2/2 - 0.2), J = [[1, y], [x, 1]], det = 1 - xy > 0 on [-0.9, 0.9]^2.
  const auto map = [](auto x, auto y) { return std::pair{x + 0.5 * sq(y) - 0.3, y + 0.5 * sq(x) - 0.2}; };
  const PlaneJacobian j = [](const IntervalVector& t) { return IntervalMatrix{{Interval(1), t[1]}, {t[0], Interval(1)}}; };
  const NewtonResult r = newton_test(box(-0.9, 0.9, -0.9, 0.9), interval_map(map), j);
  ASSERT_TRUE(r.proven);
  EXPECT_GT(r.nb_iterations, 1u);
  // The zero by point Newton iterations.
  double x = 0, y = 0;
  for (int k = 0; k < 50; ++k) {
    const double f1 = x + 0.5 * y * y - 0.3, f2 = y + 0.5 * x * x - 0.2, det = 1 - x * y;
    const double dx = (f1 - y * f2) / det, dy = (f2 - x * f1) / det;
    x -= dx;
    y -= dy;
  }
  EXPECT_TRUE(r.box.contains({x, y})) << r.box << " vs " << x << ", " << y;
  EXPECT_LT(r.box.max_diam(), 1e-3);
}

TEST(NewtonTest, UncertainFunctionProvesForTheWholeClass) {
  const double e = 0.01;
  const PlaneFunction f = [e](const IntervalVector& t) { return t + IntervalVector(2, Interval(-e, e)); };
  const NewtonResult r = newton_test(box(-1, 1, -1, 1), f, kIdentityJacobian);
  EXPECT_TRUE(r.proven);
  // Every member identity + c, |c| <= e, has its zero -c in the result.
  EXPECT_TRUE(box(-e, e, -e, e).is_subset(r.box)) << r.box;
}

TEST(NewtonTest, FailsOnADoubleZeroOrASingularJacobian) {
  // (x^2, y): a double zero, det J = 2x vanishes there.
  const auto sq_map = interval_map([](auto x, auto y) { return std::pair{sq(x), y}; });
  const PlaneJacobian j = [](const IntervalVector& t) {
    return IntervalMatrix{{2.0 * t[0], Interval(0)}, {Interval(0), Interval(1)}};
  };
  const NewtonResult r = newton_test(box(-1, 1, -1, 1), sq_map, j);
  EXPECT_FALSE(r.proven);
  EXPECT_FALSE(r.box.is_empty());
  EXPECT_TRUE(r.box.contains({0, 0}));
  // (x + y, x + y): singular everywhere.
  const auto flat = interval_map([](auto x, auto y) { return std::pair{x + y, x + y}; });
  const NewtonResult s = newton_test(box(-1, 1, -1, 1), flat, constant_jacobian(IntervalMatrix{{1, 1}, {1, 1}}));
  EXPECT_FALSE(s.proven);
  EXPECT_EQ(s.nb_iterations, 1u);
  EXPECT_EQ(s.box, box(-1, 1, -1, 1));
}

TEST(NewtonTest, EmptyWhenThereIsNoZero) {
  const auto far = interval_map([](auto x, auto y) { return std::pair{x - 5.0, y}; });
  const NewtonResult r = newton_test(box(-1, 1, -1, 1), far, kIdentityJacobian);
  EXPECT_FALSE(r.proven);
  EXPECT_TRUE(r.box.is_empty());
  const NewtonResult none = newton_test(IntervalVector::empty(2), kIdentity, kIdentityJacobian);
  EXPECT_FALSE(none.proven);
  EXPECT_TRUE(none.box.is_empty());
  EXPECT_EQ(none.nb_iterations, 0u);
}

TEST(NewtonTest, NotProvenWhenSomeMemberHasItsZeroOutside) {
  // identity + [-e, e]^2 on the box [-e/2, e/2]^2: the members identity + c,
  // |c| = e, have their zero outside. N = [-e, e]^2 sticks out of the box.
  const double e = 1e-4;
  const PlaneFunction f = [e](const IntervalVector& t) { return t + IntervalVector(2, Interval(-e, e)); };
  const NewtonResult r = newton_test(box(-e / 2, e / 2, -e / 2, e / 2), f, kIdentityJacobian);
  EXPECT_FALSE(r.proven);
  EXPECT_EQ(r.box, box(-e / 2, e / 2, -e / 2, e / 2));
  // A zero exactly on the boundary is kept, not proven (N must be interior).
  const auto on_side = interval_map([](auto x, auto y) { return std::pair{x - 1.0, y}; });
  const NewtonResult s = newton_test(box(-1, 1, -1, 1), on_side, kIdentityJacobian);
  EXPECT_FALSE(s.proven);
  EXPECT_TRUE(s.box.contains({1, 0}));
  // Just outside: nothing.
  const auto outside = interval_map([](auto x, auto y) { return std::pair{x - (1.0 + 1e-12), y}; });
  EXPECT_TRUE(newton_test(box(-1, 1, -1, 1), outside, kIdentityJacobian).box.is_empty());
}

TEST(NewtonTest, RandomAffineMapsAreNeverWrong) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coef(-2, 2), where(-3, 3);
  int proven = 0, empty = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const double a = coef(rng), b = coef(rng), c = coef(rng), d = coef(rng);
    const double zx = where(rng), zy = where(rng);
    const double bx = -(a * zx + b * zy), by = -(c * zx + d * zy);
    const auto f = interval_map([=](auto x, auto y) { return std::pair{a * x + b * y + bx, c * x + d * y + by}; });
    const IntervalVector t = box(-1, 1.5, -1.5, 1);
    const NewtonResult r = newton_test(t, f, constant_jacobian(IntervalMatrix{{a, b}, {c, d}}));
    const bool inside = t.contains({zx, zy});
    if (r.proven) {
      ++proven;
      EXPECT_TRUE(inside) << "trial " << trial;
      EXPECT_TRUE(r.box.contains({zx, zy}) || r.box.inflate(1e-12).contains({zx, zy})) << "trial " << trial;
    }
    if (r.box.is_empty()) {
      ++empty;
      // A zero far enough from the box (rounding of b moves it by ~1e-15).
      EXPECT_FALSE(t.inflate(1e-9).contains({zx, zy})) << "trial " << trial;
    }
    // An affine map with a regular A: Newton is exact up to rounding.
    if (std::abs(a * d - b * c) > 0.1 && box(-1 + 1e-6, 1.5 - 1e-6, -1.5 + 1e-6, 1 - 1e-6).contains({zx, zy})) {
      EXPECT_TRUE(r.proven) << "trial " << trial;
    }
  }
  EXPECT_GT(proven, 50);
  EXPECT_GT(empty, 100);
}

TEST(NewtonTest, BadInput) {
  EXPECT_THROW(newton_test(IntervalVector(3, Interval(0, 1)), kIdentity, kIdentityJacobian), DimensionError);
  EXPECT_THROW(newton_test(IntervalVector{Interval(0, 1), Interval::pos_reals()}, kIdentity, kIdentityJacobian),
               Error);
  EXPECT_THROW(newton_test(box(-1, 1, -1, 1), kIdentity, constant_jacobian(IntervalMatrix::identity(3))),
               DimensionError);
  const PlaneFunction one = [](const IntervalVector& t) { return IntervalVector{t[0]}; };
  EXPECT_THROW(newton_test(box(-1, 1, -1, 1), one, kIdentityJacobian), DimensionError);
}

// ---- degree T versus Newton N (Fig. 6.19b) ----

TEST(NearParallelCrossing, DegreeProvesWhereNewtonCannot) {
  const NearParallel np;
  const std::vector<IntervalVector> omega{np.region()};
  const DegreeResult d = topological_degree(omega, np.f());
  ASSERT_TRUE(d.degree);
  EXPECT_EQ(*d.degree, -1);  // det g' = -δ < 0
  // The velocity uncertainty makes [J] possibly singular: N concludes nothing.
  const NewtonResult n = newton_test(np.region(), np.f(), np.jacobian());
  EXPECT_FALSE(n.proven);
  EXPECT_FALSE(n.box.is_empty());
  // Members of the class: positions perturbed by less than e.
  for (int k = 1; k <= 3; ++k) {
    const double delta = np.delta, e = np.e;
    const auto member = [=](auto t1, auto t2) {
      using std::sin;
      return std::pair{t2 - t1 + 0.9 * e * sin(double(k) * 40.0 * t1), delta * t2 + 0.9 * e * sin(t1 + double(k) * 30.0 * t2)};
    };
    EXPECT_NEAR(sampled_winding(contour(omega), point_map(member)), -1.0, 1e-6) << "member " << k;
  }
  // The same crossing with exactly known velocities: Newton proves it too.
  const PlaneJacobian exact = constant_jacobian(IntervalMatrix{{-1, 1}, {0, np.delta}});
  EXPECT_TRUE(newton_test(np.region(), np.f(), exact).proven);
}

TEST(NearParallelCrossing, RobustZeroWithSingularJacobian) {
  // (x^3, y + e): the zero is robust (degree 1) but J = diag(3x^2, 1) is singular at it.
  const double e = 0.01;
  const PlaneFunction f = [e](const IntervalVector& t) {
    return IntervalVector{t[0] * sq(t[0]) + Interval(-e, e), t[1] + Interval(-e, e)};
  };
  const PlaneJacobian j = [](const IntervalVector& t) {
    return IntervalMatrix{{3.0 * sq(t[0]), Interval(0)}, {Interval(0), Interval(1)}};
  };
  EXPECT_EQ(topological_degree({box(-1, 1, -1, 1)}, f).degree, 1);
  EXPECT_FALSE(newton_test(box(-1, 1, -1, 1), f, j).proven);
}

// ---- count (Alg. 10) ----

TEST(CountZeros, OneSimpleZero) {
  const std::vector<IntervalVector> omega{box(-1, 1, -1, 1)};
  const DegreeResult d = topological_degree(omega, kIdentity);
  ASSERT_EQ(d.degree, 1);
  const CountResult c = count_zeros(omega, *d.degree, kIdentity, kIdentityJacobian);
  EXPECT_EQ(c.count, 1u);
  EXPECT_EQ(c.nb_boxes, 1u);
}

TEST(CountZeros, TwoZerosOfTheSameOrientation) {
  const std::vector<IntervalVector> omega{box(-2, 2, -1, 1)};
  const PlaneFunction f = interval_map(kZ2m1);
  const DegreeResult d = topological_degree(omega, f);
  ASSERT_EQ(d.degree, 2);
  // det J = 4|z|^2 vanishes at 0 only, where f = (-1, 0): bisected, then dropped.
  const CountResult c = count_zeros(omega, 2, f, kZ2Jacobian);
  EXPECT_EQ(c.count, 2u);
  EXPECT_GT(c.nb_boxes, 1u);
  // Also over a union of boxes with a pinch point.
  const std::vector<IntervalVector> pinch{box(-1, 0, -1, 0), box(0, 1, 0, 1)};
  const auto two = interval_map([](auto x, auto y) { return std::pair{(x - 0.5) * (x + 0.5), (y - 0.5) * (y + 0.5)}; });
  const PlaneJacobian jtwo = [](const IntervalVector& t) {
    return IntervalMatrix{{2.0 * t[0], Interval(0)}, {Interval(0), 2.0 * t[1]}};
  };
  ASSERT_EQ(topological_degree(pinch, two).degree, 2);
  EXPECT_EQ(count_zeros(pinch, 2, two, jtwo).count, 2u);
}

TEST(CountZeros, OppositeOrientationsCannotBeCounted) {
  // (x^2 - 1, y): two zeros, degree 0, det J = 2x of both signs.
  const std::vector<IntervalVector> omega{box(-2, 2, -1, 1)};
  const auto f = interval_map([](auto x, auto y) { return std::pair{sq(x) - 1.0, y}; });
  const PlaneJacobian j = [](const IntervalVector& t) {
    return IntervalMatrix{{2.0 * t[0], Interval(0)}, {Interval(0), Interval(1)}};
  };
  ASSERT_EQ(topological_degree(omega, f).degree, 0);
  EXPECT_FALSE(count_zeros(omega, 0, f, j).count);
  // Each half alone is counted.
  EXPECT_EQ(count_zeros({box(0, 2, -1, 1)}, 1, f, j).count, 1u);
  EXPECT_EQ(count_zeros({box(-2, 0, -1, 1)}, -1, f, j).count, 1u);
}

TEST(CountZeros, SingularAtTheZeroIsUndetermined) {
  // z^2 at 0: degree 2, det J = 4|z|^2 contains 0 on every box around the zero.
  const std::vector<IntervalVector> omega{box(-1, 1, -1, 1)};
  const auto f = interval_map([](auto x, auto y) { return std::pair{sq(x) - sq(y), 2.0 * x * y}; });
  ASSERT_EQ(topological_degree(omega, f).degree, 2);
  CountOptions o;
  o.min_width = 1e-3;
  EXPECT_FALSE(count_zeros(omega, 2, f, kZ2Jacobian, o).count);
  // The box cap stops it earlier.
  o.min_width = 1e-12;
  o.max_boxes = 16;
  const CountResult c = count_zeros(omega, 2, f, kZ2Jacobian, o);
  EXPECT_FALSE(c.count);
  EXPECT_LE(c.nb_boxes, 16u);
}

TEST(CountZeros, NoZeroGivesZero) {
  const std::vector<IntervalVector> omega{box(1, 2, 1, 2)};
  ASSERT_EQ(topological_degree(omega, kIdentity).degree, 0);
  EXPECT_EQ(count_zeros(omega, 0, kIdentity, kIdentityJacobian).count, 0u);
  // (x - 2.5, y) through a loose inclusion function: f may vanish on the
  // boxes, det J = 1 > 0 and the degree is 0, so there is no zero (0 = +1 · N).
  const PlaneFunction loose = [](const IntervalVector& t) {
    const Interval w = t.max_diam() * Interval(-1, 1);
    return IntervalVector{t[0] - 2.5 + w, t[1] + w};
  };
  const std::vector<IntervalVector> near{box(0, 2, -1, 1), box(2, 2.4, -1, 1)};
  ASSERT_EQ(topological_degree(near, loose).degree, 0);
  const CountResult c = count_zeros(near, 0, loose, kIdentityJacobian);
  EXPECT_EQ(c.count, 0u);
  EXPECT_EQ(c.nb_boxes, 2u);
}

TEST(CountZeros, RefinesAPessimisticJacobian) {
  // Remark 6.1: J = I enclosed by I + width([t]) [-1, 1]: singular on wide
  // boxes, regular on small ones.
  const PlaneJacobian wide = [](const IntervalVector& t) {
    const Interval w = t.max_diam() * Interval(-1, 1);
    return IntervalMatrix{{1.0 + w, w}, {w, 1.0 + w}};
  };
  const std::vector<IntervalVector> omega{box(-1, 1, -1, 1)};
  const CountResult c = count_zeros(omega, 1, kIdentity, wide);
  EXPECT_EQ(c.count, 1u);
  EXPECT_GT(c.nb_boxes, 4u);
  // Without room to refine: no conclusion.
  CountOptions o;
  o.min_width = 3;
  EXPECT_FALSE(count_zeros(omega, 1, kIdentity, wide, o).count);
}

TEST(CountZeros, ContradictionsAreNotCounts) {
  const std::vector<IntervalVector> omega{box(-1, 1, -1, 1)};
  // A degree of the wrong sign for det J > 0, or a degree without any zero.
  EXPECT_FALSE(count_zeros(omega, -1, kIdentity, kIdentityJacobian).count);
  EXPECT_FALSE(count_zeros({box(1, 2, 1, 2)}, 1, kIdentity, kIdentityJacobian).count);
}

TEST(CountZeros, BadInput) {
  EXPECT_THROW(count_zeros({}, 0, kIdentity, kIdentityJacobian), Error);
  CountOptions o;
  o.min_width = 0;
  EXPECT_THROW(count_zeros({box(-1, 1, -1, 1)}, 1, kIdentity, kIdentityJacobian, o), Error);
  EXPECT_THROW(count_zeros({IntervalVector(3, Interval(0, 1))}, 1, kIdentity, kIdentityJacobian), DimensionError);
  EXPECT_THROW(count_zeros({box(-1, 1, -1, 1)}, 1, kIdentity, constant_jacobian(IntervalMatrix(2, 3, Interval(0)))),
               DimensionError);
}
