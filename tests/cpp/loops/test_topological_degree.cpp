// The degree test T of thesis 6.3.2-6.3.3 (Theorem 6.1, Alg. 7-9 with
// boundary refinement): analytic maps of known degree, unions with holes,
// L shapes and pinch points, uncertain maps, and property tests against the
// mathematical degree of affine maps and a sampled winding number.
#include <gtest/gtest.h>

#include <random>

#include "plane_maps.h"
#include "sillage/interval/elementary.h"
#include "sillage/loops/topological_degree.h"

using namespace sillage;
using namespace sillage::test;

namespace {

// f(x, y) = (x - cx, y - cy): the zero at (cx, cy), Jacobian the identity.
PlaneFunction shifted_identity(double cx, double cy) {
  return interval_map([cx, cy](auto x, auto y) { return std::pair{x - cx, y - cy}; });
}

std::optional<int> degree_on(const std::vector<IntervalVector>& boxes, const PlaneFunction& f) {
  return topological_degree(boxes, f).degree;
}

const auto kZ2 = [](auto x, auto y) { return std::pair{sq(x) - sq(y), 2.0 * x * y}; };                 // z^2
const auto kZ3 = [](auto x, auto y) { return std::pair{x * (sq(x) - 3.0 * sq(y)), y * (3.0 * sq(x) - sq(y))}; };  // z^3
const auto kConjZ2 = [](auto x, auto y) { return std::pair{sq(x) - sq(y), -2.0 * x * y}; };            // conj(z)^2

}  // namespace

TEST(TopologicalDegree, IdentityOnACounterClockwiseSquareIsOne) {
  const DegreeResult r = topological_degree({box(-1, 1, -1, 1)}, shifted_identity(0, 0));
  ASSERT_TRUE(r.degree);
  EXPECT_EQ(*r.degree, 1);
  EXPECT_TRUE(r.proves_zero());
  // Every whole edge already excludes 0: no refinement.
  EXPECT_EQ(r.nb_pieces, 4u);
  EXPECT_EQ(r.nb_evaluations, 4u);
  EXPECT_EQ(r.nb_unresolved, 0u);
}

TEST(TopologicalDegree, ReflectionIsMinusOne) {
  const auto f = interval_map([](auto x, auto y) { return std::pair{x, -y}; });
  EXPECT_EQ(degree_on({box(-1, 1, -2, 0.5)}, f), -1);
}

TEST(TopologicalDegree, ComplexPowersGiveTheirMultiplicity) {
  EXPECT_EQ(degree_on({box(-1, 1, -1, 1)}, interval_map(kZ2)), 2);
  EXPECT_EQ(degree_on({box(-1, 2, -0.5, 1)}, interval_map(kZ3)), 3);
  EXPECT_EQ(degree_on({box(-1, 1, -1, 1)}, interval_map(kConjZ2)), -2);
  // The same maps around a region without their zero.
  EXPECT_EQ(degree_on({box(0.5, 2, -1, 1)}, interval_map(kZ2)), 0);
  EXPECT_EQ(degree_on({box(0.5, 2, -1, 1)}, interval_map(kZ3)), 0);
}

TEST(TopologicalDegree, RegionWithoutTheZeroIsZero) {
  EXPECT_EQ(degree_on({box(1, 2, -1, 1)}, shifted_identity(0, 0)), 0);
  EXPECT_EQ(degree_on({box(-1, 1, -1, 1)}, shifted_identity(5, -3)), 0);
  // degree 0 proves nothing
  EXPECT_FALSE(topological_degree({box(1, 2, -1, 1)}, shifted_identity(0, 0)).proves_zero());
}

TEST(TopologicalDegree, HoleLoopCountsWithItsClockwiseOrientation) {
  // A ring of eight unit... boxes of side 2 around the hole [-1, 1]^2.
  std::vector<IntervalVector> ring;
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      if (i != 0 || j != 0) ring.push_back(box(2 * i - 1, 2 * i + 1, 2 * j - 1, 2 * j + 1));
    }
  }
  const auto loops = contour(ring);
  ASSERT_EQ(loops.size(), 2u);
  ASSERT_FALSE(loops[0].is_hole);
  ASSERT_TRUE(loops[1].is_hole);
  const PlaneFunction f = shifted_identity(0, 0);  // the zero is in the hole
  EXPECT_EQ(topological_degree(std::vector<ContourLoop>{loops[0]}, f).degree, 1);
  EXPECT_EQ(topological_degree(std::vector<ContourLoop>{loops[1]}, f).degree, -1);
  EXPECT_EQ(topological_degree(loops, f).degree, 0);
  EXPECT_EQ(degree_on(ring, f), 0);
  // The zero in the body of the ring: the hole loop does not wind around it.
  const PlaneFunction g = shifted_identity(2, 0.5);
  EXPECT_EQ(topological_degree(std::vector<ContourLoop>{loops[1]}, g).degree, 0);
  EXPECT_EQ(degree_on(ring, g), 1);
}

TEST(TopologicalDegree, LShapedUnion) {
  const std::vector<IntervalVector> l{box(0, 2, 0, 1), box(0, 1, 1, 2)};
  EXPECT_EQ(degree_on(l, shifted_identity(0.5, 1.5)), 1);   // in the upper arm
  EXPECT_EQ(degree_on(l, shifted_identity(1.5, 0.25)), 1);  // in the right arm
  EXPECT_EQ(degree_on(l, shifted_identity(1.5, 1.5)), 0);   // in the notch
  EXPECT_EQ(degree_on(l, shifted_identity(0.5, 1.0)), 1);   // on the inner side shared by the boxes
}

TEST(TopologicalDegree, PinchedUnion) {
  const std::vector<IntervalVector> pinch{box(-1, 0, -1, 0), box(0, 1, 0, 1)};
  EXPECT_EQ(degree_on(pinch, shifted_identity(0.5, 0.5)), 1);
  EXPECT_EQ(degree_on(pinch, shifted_identity(-0.5, -0.25)), 1);
  EXPECT_EQ(degree_on(pinch, shifted_identity(-0.5, 0.5)), 0);
  // Zeros (±1/2, ±1/2): (1/2, 1/2) and (-1/2, -1/2) are inside, both with det J = 4xy > 0.
  const auto two = interval_map([](auto x, auto y) { return std::pair{(x - 0.5) * (x + 0.5), (y - 0.5) * (y + 0.5)}; });
  EXPECT_EQ(degree_on(pinch, two), 2);
  // The zero at the pinch point is on the boundary: undetermined.
  DegreeOptions o;
  o.min_edge_length = 1e-6;
  const DegreeResult r = topological_degree(pinch, shifted_identity(0, 0), o);
  EXPECT_FALSE(r.degree);
  EXPECT_GE(r.nb_unresolved, 1u);
}

TEST(TopologicalDegree, ZerosOfOppositeAndEqualOrientations) {
  const auto omega = std::vector<IntervalVector>{box(-2, 2, -1, 1)};
  // (x^2 - 1, y): zeros (±1, 0) with det J = 2x of opposite signs.
  EXPECT_EQ(degree_on(omega, interval_map([](auto x, auto y) { return std::pair{sq(x) - 1.0, y}; })), 0);
  // (x^2 - 1, x y): det J = 2x^2 > 0 at both zeros.
  EXPECT_EQ(degree_on(omega, interval_map([](auto x, auto y) { return std::pair{sq(x) - 1.0, x * y}; })), 2);
  // z^2 - 1.
  EXPECT_EQ(degree_on(omega, interval_map([](auto x, auto y) { return std::pair{sq(x) - sq(y) - 1.0, 2.0 * x * y}; })),
            2);
  // Only one of the two zeros of (x^2 - 1, y) in the region.
  EXPECT_EQ(degree_on({box(0, 2, -1, 1)}, interval_map([](auto x, auto y) { return std::pair{sq(x) - 1.0, y}; })), 1);
  EXPECT_EQ(degree_on({box(-2, 0, -1, 1)}, interval_map([](auto x, auto y) { return std::pair{sq(x) - 1.0, y}; })), -1);
}

TEST(TopologicalDegree, EdgeThroughTheZeroIsUndetermined) {
  DegreeOptions o;
  o.min_edge_length = 1e-6;
  const DegreeResult r = topological_degree({box(0, 1, -1, 1)}, shifted_identity(0, 0), o);
  EXPECT_FALSE(r.degree);
  EXPECT_FALSE(r.proves_zero());
  EXPECT_GE(r.nb_unresolved, 1u);
  // The refinement around the zero stops at the floor: logarithmic work, not more.
  EXPECT_LT(r.nb_evaluations, 200u);
  EXPECT_GT(r.nb_evaluations, 20u);
}

TEST(TopologicalDegree, RefinedEdgesConcludeWhereWholeEdgesCannot) {
  // (x + y, y - x): on the bottom edge y = -1, f1 = x - 1 and f2 = -1 - x both
  // contain 0 over x ∈ [-1, 1]; each half excludes it. det J = 2 > 0.
  const auto f = interval_map([](auto x, auto y) { return std::pair{x + y, y - x}; });
  const DegreeResult r = topological_degree({box(-1, 1, -1, 1)}, f);
  ASSERT_TRUE(r.degree);
  EXPECT_EQ(*r.degree, 1);
  EXPECT_EQ(r.nb_pieces, 8u);
  EXPECT_EQ(r.nb_evaluations, 12u);  // 4 whole edges, then 8 halves
  // Without room to bisect (edges of length 2 below the floor) it cannot conclude.
  DegreeOptions o;
  o.min_edge_length = 3;
  const DegreeResult coarse = topological_degree({box(-1, 1, -1, 1)}, f, o);
  EXPECT_FALSE(coarse.degree);
  EXPECT_EQ(coarse.nb_unresolved, 4u);
  EXPECT_EQ(coarse.nb_evaluations, 4u);
}

TEST(TopologicalDegree, EvaluationBudgetIsRespected) {
  DegreeOptions o;
  o.max_evaluations = 10;
  const DegreeResult r = topological_degree({box(0, 1, -1, 1)}, shifted_identity(0, 0), o);
  EXPECT_FALSE(r.degree);
  EXPECT_EQ(r.nb_evaluations, 10u);
  EXPECT_GE(r.nb_unresolved, 1u);
  // A budget large enough for the refinement of the rotated map.
  o.max_evaluations = 12;
  const auto f = interval_map([](auto x, auto y) { return std::pair{x + y, y - x}; });
  EXPECT_EQ(topological_degree({box(-1, 1, -1, 1)}, f, o).degree, 1);
  o.max_evaluations = 11;
  EXPECT_FALSE(topological_degree({box(-1, 1, -1, 1)}, f, o).degree);
}

TEST(TopologicalDegree, StartingEdgeAndOrientation) {
  const auto loops = contour({box(0, 2, 0, 1), box(0, 1, 1, 2), box(2, 3, 0, 3)});
  ASSERT_EQ(loops.size(), 1u);
  const PlaneFunction f = interval_map(kZ3);
  // z^3 - shifted so that the zero (1/2, 1/2) is inside: a degree 3.
  const PlaneFunction g = [&f](const IntervalVector& t) {
    return f(IntervalVector{t[0] - Interval(0.5), t[1] - Interval(0.5)});
  };
  ASSERT_EQ(topological_degree(loops, g).degree, 3);
  for (std::size_t k = 0; k < loops[0].edges.size(); ++k) {
    EXPECT_EQ(topological_degree(std::vector<ContourLoop>{rotated(loops[0], k)}, g).degree, 3) << "start " << k;
    EXPECT_EQ(topological_degree(std::vector<ContourLoop>{reversed(rotated(loops[0], k))}, g).degree, -3);
  }
}

TEST(TopologicalDegree, UncertainMapConcludesForEveryMember) {
  // [f] = z^3 + [-e, e]^2 around 0: degree 3 for every f* in it.
  const double e = 0.05;
  const Interval noise(-e, e);
  const PlaneFunction uncertain = [&](const IntervalVector& t) {
    auto [u, v] = kZ3(t[0], t[1]);
    return IntervalVector{u + noise, v + noise};
  };
  const auto omega = std::vector<IntervalVector>{box(-1, 1, -0.75, 1.25)};
  ASSERT_EQ(degree_on(omega, uncertain), 3);
  // Members f*_k = z^3 + 0.9 e (sin(k x + y), cos(x - k y)): tight inclusion
  // functions and a sampled winding number agree.
  for (int k = 1; k <= 4; ++k) {
    const auto member = [k, e](auto x, auto y) {
      auto [u, v] = kZ3(x, y);
      using std::cos, std::sin;
      return std::pair{u + 0.9 * e * sin(double(k) * x + y), v + 0.9 * e * cos(x - double(k) * y)};
    };
    EXPECT_EQ(degree_on(omega, interval_map(member)), 3) << "member " << k;
    EXPECT_NEAR(sampled_winding(contour(omega), point_map(member)), 3.0, 1e-6) << "member " << k;
  }
  // Too much uncertainty for the boundary: undetermined, never wrong.
  const Interval big(-2, 2);
  const PlaneFunction vague = [&](const IntervalVector& t) {
    auto [u, v] = kZ3(t[0], t[1]);
    return IntervalVector{u + big, v + big};
  };
  DegreeOptions o;
  o.min_edge_length = 1e-3;
  EXPECT_FALSE(topological_degree(omega, vague, o).degree);
}

TEST(TopologicalDegree, DeterministicAndReentrant) {
  const auto cells = std::vector<IntervalVector>{box(0, 1, 0, 1), box(1, 2, 0, 1), box(1, 2, 1, 2)};
  const auto f = interval_map([](auto x, auto y) { return std::pair{sq(x) - sq(y) - 1.0, 2.0 * x * y - 0.5}; });
  const DegreeResult a = topological_degree(cells, f);
  const DegreeResult b = topological_degree(cells, f);
  EXPECT_EQ(a.degree, b.degree);
  EXPECT_EQ(a.nb_evaluations, b.nb_evaluations);
  EXPECT_EQ(a.nb_pieces, b.nb_pieces);
}

TEST(TopologicalDegree, RandomAffineMapsHaveTheSignOfTheirDeterminant) {
  std::mt19937 rng(20170613);
  std::uniform_real_distribution<double> coef(-2, 2), where(-2, 2);
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto cells = random_cells(rng, 4, -2, 2, 0.5);
    const double a = coef(rng), b = coef(rng), c = coef(rng), d = coef(rng);
    const double det = a * d - b * c;
    if (std::abs(det) < 0.05) continue;
    const double zx = where(rng), zy = where(rng);
    // Away from every grid line: not on the boundary of the region.
    if (std::abs(zx - std::round(zx)) < 1e-3 || std::abs(zy - std::round(zy)) < 1e-3) continue;
    bool in = false;
    for (const auto& cell : cells) in = in || cell.contains({zx, zy});
    const double bx = -(a * zx + b * zy), by = -(c * zx + d * zy);
    const auto f = interval_map([=](auto x, auto y) { return std::pair{a * x + b * y + bx, c * x + d * y + by}; });
    const DegreeResult r = topological_degree(cells, f);
    ASSERT_TRUE(r.degree) << "trial " << trial;
    EXPECT_EQ(*r.degree, in ? (det > 0 ? 1 : -1) : 0) << "trial " << trial << " zero (" << zx << ", " << zy << ")";
    (in ? inside : outside) += 1;
  }
  EXPECT_GT(inside, 50);
  EXPECT_GT(outside, 50);
}

TEST(TopologicalDegree, RandomQuadraticMapsAgreeWithTheSampledWindingNumber) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> coef(-1, 1);
  int determined = 0, nonzero = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const auto cells = random_cells(rng, 5, -2, 2, 0.55);
    double p[6], q[6];
    for (double& x : p) x = coef(rng);
    for (double& x : q) x = coef(rng);
    const auto map = [p, q](auto x, auto y) {
      return std::pair{p[0] + p[1] * x + p[2] * y + p[3] * sq(x) + p[4] * x * y + p[5] * sq(y),
                       q[0] + q[1] * x + q[2] * y + q[3] * sq(x) + q[4] * x * y + q[5] * sq(y)};
    };
    DegreeOptions o;
    o.max_evaluations = 200000;
    const DegreeResult r = topological_degree(cells, interval_map(map), o);
    if (!r.degree) continue;  // a zero on (or extremely near) the boundary
    ++determined;
    nonzero += *r.degree != 0;
    const double w = sampled_winding(contour(cells), point_map(map));
    EXPECT_NEAR(w, double(*r.degree), 1e-6) << "trial " << trial;
  }
  EXPECT_GT(determined, 190);
  EXPECT_GT(nonzero, 40);
}

TEST(TopologicalDegree, BadInput) {
  const PlaneFunction f = shifted_identity(0, 0);
  EXPECT_THROW(topological_degree(std::vector<ContourLoop>{}, f), Error);
  EXPECT_THROW(topological_degree(std::vector<IntervalVector>{}, f), Error);
  EXPECT_THROW(topological_degree({box(0, 1, 0, 0)}, f), Error);  // no interior, no boundary
  EXPECT_THROW(topological_degree({IntervalVector{Interval(0, 1), Interval(0, 1), Interval(0, 1)}}, f),
               DimensionError);
  DegreeOptions o;
  o.min_edge_length = 0;
  EXPECT_THROW(topological_degree({box(-1, 1, -1, 1)}, f, o), Error);
  o.min_edge_length = -1;
  EXPECT_THROW(topological_degree({box(-1, 1, -1, 1)}, f, o), Error);
  o.min_edge_length = std::nan("");
  EXPECT_THROW(topological_degree({box(-1, 1, -1, 1)}, f, o), Error);
  o = {};
  o.max_evaluations = 0;
  EXPECT_THROW(topological_degree({box(-1, 1, -1, 1)}, f, o), Error);

  ContourLoop open;
  open.edges = {{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 1}}};
  EXPECT_THROW(topological_degree(std::vector<ContourLoop>{open}, f), Error);
  ContourLoop slanted;
  slanted.edges = {{{0, 0}, {1, 0}}, {{1, 0}, {0, 1}}, {{0, 1}, {0, 0}}};
  EXPECT_THROW(topological_degree(std::vector<ContourLoop>{slanted}, f), Error);
  EXPECT_THROW(topological_degree(std::vector<ContourLoop>{ContourLoop{}}, f), Error);

  // Callables breaking their contract.
  const PlaneFunction three = [](const IntervalVector& t) { return IntervalVector{t[0], t[1], t[0]}; };
  EXPECT_THROW(topological_degree({box(-1, 1, -1, 1)}, three), DimensionError);
  const PlaneFunction hollow = [](const IntervalVector&) { return IntervalVector::empty(2); };
  EXPECT_THROW(topological_degree({box(-1, 1, -1, 1)}, hollow), Error);
  // f1 jumps from -1 to +1 across x = 0, on the two halves of the bottom edge
  // (whole edges straddle 0 and are bisected there): no f* has such an enclosure.
  const PlaneFunction jump = [](const IntervalVector& t) {
    const Interval f1 = t[0].ub() <= 0 ? Interval(-1) : t[0].lb() >= 0 ? Interval(1) : Interval(-1, 1);
    return IntervalVector{f1, Interval(-1, 1)};
  };
  EXPECT_THROW(topological_degree({box(-1, 1, -1, 1)}, jump), Error);
}
