// SIVIA (thesis Alg. 1), its contractor/separator variants and kernel SIVIA
// (Alg. 2): exact trees on small cases, and guarantee properties on random
// samples (a point proven in/out is never misclassified).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "sillage/paving/sivia.h"

using namespace sillage;

namespace {

IntervalVector box(double a, double b, double c, double d) { return {Interval(a, b), Interval(c, d)}; }

// The disk x^2 + y^2 <= 1 as f^-1([0, 1]).
IntervalVector disk_f(const IntervalVector& x) { return IntervalVector{sqr(x[0]) + sqr(x[1])}; }

bool sure_in_disk(double x, double y) { return (sqr(Interval(x)) + sqr(Interval(y))).ub() <= 1; }
bool sure_out_disk(double x, double y) { return (sqr(Interval(x)) + sqr(Interval(y))).lb() > 1; }

// Checks the invariants of a paving: node boxes are the union of their
// children, leaves cover the domain.
void expect_well_formed(const Paving& p) {
  double leaves_volume = 0;
  for (std::size_t i = 0; i < p.nb_nodes(); ++i) {
    if (p.is_leaf(i)) {
      leaves_volume += p.node_box(i).volume();
      continue;
    }
    const auto b = p.node_box(i), l = p.node_box(p.left(i)), r = p.node_box(p.right(i));
    EXPECT_EQ(l | r, b);
    EXPECT_TRUE(l.is_subset(b) && r.is_subset(b));
    // Children share at most a face.
    const auto m = l & r;
    EXPECT_TRUE(m.is_empty() || m.volume() == 0.0);
  }
  EXPECT_NEAR(leaves_volume, p.domain().volume(), 1e-9 * p.domain().volume());
}

}  // namespace

TEST(Sivia, ExactTreeIn1D) {
  // X0 = [0,1], f(x) = x, Y = [0.25, 0.75], eps = 0.25 (boxes of width 0.25 are still bisected).
  auto p = sivia(IntervalVector{Interval(0, 1)}, [](const IntervalVector& x) { return x; }, Interval(0.25, 0.75),
                 0.25);
  using T = PavingTag;
  const std::vector<std::pair<Interval, T>> expected{
      {Interval(0, 0.125), T::Outside}, {Interval(0.125, 0.25), T::Boundary}, {Interval(0.25, 0.5), T::Inner},
      {Interval(0.5, 0.75), T::Inner},  {Interval(0.75, 0.875), T::Boundary}, {Interval(0.875, 1), T::Outside}};
  std::vector<std::pair<Interval, T>> leaves;
  for (std::size_t i = 0; i < p.nb_nodes(); ++i) {
    if (p.is_leaf(i)) leaves.push_back({p.node_box(i)[0], p.tag(i)});
  }
  EXPECT_EQ(leaves, expected);
  EXPECT_EQ(p.nb_nodes(), 11u);
  EXPECT_EQ(p.nb_leaves(), 6u);
  EXPECT_EQ(p.count(T::Inner), 2u);
  EXPECT_EQ(p.volume(T::Inner), 0.5);
  EXPECT_EQ(p.volume(T::Boundary), 0.25);
  EXPECT_EQ(p.outer_volume(), 0.75);
  EXPECT_EQ(p.hull(), IntervalVector{Interval(0.125, 0.875)});
  EXPECT_EQ(p.outer().size(), 4u);
  EXPECT_EQ(p.outside().size(), 2u);
  EXPECT_EQ(*p.tag_at({0.3}), T::Inner);
  EXPECT_EQ(*p.tag_at({0.0625}), T::Outside);
  EXPECT_EQ(*p.tag_at({0.25}), T::Boundary);  // on the face between Boundary and Inner
  EXPECT_EQ(*p.tag_at({0.5}), T::Inner);      // both neighbours Inner
  EXPECT_FALSE(p.tag_at({1.5}).has_value());
  expect_well_formed(p);
}

TEST(Sivia, BisectsTheLargestDimensionFirstIndexOnTies) {
  auto p = sivia(box(0, 1, 0, 1), disk_f, Interval(0.5, 0.6), 0.1);
  ASSERT_FALSE(p.is_leaf(0));
  EXPECT_EQ(p.node_box(p.left(0)), box(0, 0.5, 0, 1));  // tie: dimension 0
  EXPECT_EQ(p.node_box(p.right(0)), box(0.5, 1, 0, 1));
  const std::size_t l = p.left(0);
  ASSERT_FALSE(p.is_leaf(l));
  EXPECT_EQ(p.node_box(p.left(l)), box(0, 0.5, 0, 0.5));  // then the wider dimension 1
  auto q = sivia(box(0, 1, 0, 3), disk_f, Interval(0.5, 0.6), 0.1);
  EXPECT_EQ(q.node_box(q.left(0)), box(0, 1, 0, 1.5));
}

TEST(Sivia, DiskGuarantees) {
  const double eps = 0.02;
  auto p = sivia(box(-2, 2, -2, 2), disk_f, Interval(0, 1), eps);
  expect_well_formed(p);
  const double pi = 3.141592653589793;
  EXPECT_LT(p.volume(PavingTag::Inner), pi);
  EXPECT_GT(p.outer_volume(), pi);
  EXPECT_LT(p.outer_volume() - p.volume(PavingTag::Inner), 2 * pi * 2 * eps * 1.5);
  for (const auto& b : p.boundary()) EXPECT_LT(b.max_diam(), eps);
  EXPECT_TRUE(p.hull().is_subset(box(-1, 1, -1, 1).inflate(eps)));
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int k = 0; k < 20000; ++k) {
    const double x = u(rng), y = u(rng);
    const auto t = p.tag_at({x, y});
    ASSERT_TRUE(t.has_value());
    if (sure_in_disk(x, y)) {
      EXPECT_NE(*t, PavingTag::Outside) << x << " " << y;
    }
    if (sure_out_disk(x, y)) {
      EXPECT_NE(*t, PavingTag::Inner) << x << " " << y;
    }
  }
  // Points sampled inside inner boxes are in X; inside outside boxes, not.
  for (const auto& b : p.inner()) EXPECT_FALSE(sure_out_disk(b[0].mid(), b[1].mid()));
  for (const auto& b : p.outside()) EXPECT_FALSE(sure_in_disk(b[0].mid(), b[1].mid()));
  // The disk is one component; outer() is its list of boxes.
  auto comps = p.components();
  ASSERT_EQ(comps.size(), 1u);
  EXPECT_EQ(comps[0].size(), p.outer().size());
  EXPECT_EQ(comps[0].hull, p.hull());
  auto loops = comps[0].contour();
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_FALSE(loops[0].is_hole);
}

TEST(Sivia, RingHasAHoleAndBoundaryBoxesOnlyOnTheCircles) {
  auto p = sivia(box(-2, 2, -2, 2), disk_f, Interval(0.5, 2.0), 0.05);
  auto comps = p.components();
  ASSERT_EQ(comps.size(), 1u);
  auto loops = comps[0].contour();
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_FALSE(loops[0].is_hole);
  EXPECT_TRUE(loops[1].is_hole);
  for (const auto& b : p.boundary()) {
    const Interval r2 = sqr(b[0]) + sqr(b[1]);
    EXPECT_TRUE(r2.contains(0.5) || r2.contains(2.0)) << b;
  }
}

TEST(Sivia, ComponentsOfSeparatedSets) {
  // (x^2 - 1)^2 + y^2 <= 0.1: two blobs around (-1, 0) and (1, 0).
  auto f = [](const IntervalVector& x) { return IntervalVector{sqr(sqr(x[0]) - Interval(1.0)) + sqr(x[1])}; };
  auto p = sivia(box(-2, 2, -1, 1), f, Interval(0, 0.1), 0.01);
  auto comps = p.components();
  ASSERT_EQ(comps.size(), 2u);
  EXPECT_LT(comps[0].hull[0].ub(), 0.0);  // ordered by first box in pre-order: left blob first
  EXPECT_GT(comps[1].hull[0].lb(), 0.0);
  double v = 0;
  std::size_t n = 0;
  for (const auto& c : comps) {
    v += c.volume;
    n += c.size();
    EXPECT_EQ(c.count(PavingTag::Inner) + c.count(PavingTag::Boundary), c.size());
  }
  EXPECT_EQ(n, p.outer().size());
  EXPECT_NEAR(v, p.outer_volume(), 1e-12);
}

TEST(Sivia, VectorValuedFunctionAndEmptyImages) {
  // X = {x : x0 in [0,1], sqrt(x1) in [0.5, 1]}: sqrt is empty for x1 < 0, which proves the box out.
  auto f = [](const IntervalVector& x) { return IntervalVector{x[0], sqrt(x[1])}; };
  auto p = sivia(box(-1, 2, -1, 2), f, box(0, 1, 0.5, 1), 0.05);
  for (const auto& b : p.inner()) {
    EXPECT_TRUE(b[0].is_subset(Interval(0, 1)));
    EXPECT_TRUE(b[1].is_subset(Interval(0.25, 1)));
  }
  EXPECT_TRUE(p.hull().is_subset(box(-0.05, 1.05, 0.2, 1.05)));
  EXPECT_NEAR(p.volume(PavingTag::Inner), 0.75, 0.2);
}

TEST(Sivia, ContractorVariantIsAnOuterApproximation) {
  // Contractor of the disk: intersect each coordinate with the projection
  // given by the other one (x^2 <= 1 - y^2).
  auto ctc = [](IntervalVector& x) {
    for (int pass = 0; pass < 2; ++pass) {
      for (int i = 0; i < 2; ++i) {
        const Interval rest = Interval(1.0) - sqr(x[1 - i]);
        if (rest.ub() < 0) {
          x.set_empty();
          return;
        }
        const Interval r = sqrt(rest & Interval::pos_reals());
        x[i] &= r | -r;
        if (x.is_empty()) {
          x.set_empty();
          return;
        }
      }
    }
  };
  auto p = sivia_contractor(box(-2, 2, -2, 2), ctc, 0.05);
  expect_well_formed(p);
  EXPECT_EQ(p.count(PavingTag::Inner), 0u);
  auto plain = sivia(box(-2, 2, -2, 2), disk_f, Interval(0, 1), 0.05);
  for (const auto& b : p.boundary()) EXPECT_LT(b.max_diam(), 0.05);
  // No inner test: the interior of the disk is bisected down to eps too.
  EXPECT_GT(p.count(PavingTag::Boundary), plain.count(PavingTag::Boundary));
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 5000; ++k) {
    const double x = u(rng), y = u(rng);
    if (sure_in_disk(x, y)) {
      EXPECT_EQ(*p.tag_at({x, y}), PavingTag::Boundary);
    }
  }
  EXPECT_GT(p.outer_volume(), 3.14159);
}

TEST(Sivia, SeparatorVariantTagsTheRemovedParts) {
  // Separator for the half-plane x0 + x1 <= 1 on boxes, plus a test.
  auto sep = [](IntervalVector& x_in, IntervalVector& x_out) {
    // Outer: x0 <= 1 - x1.lb, x1 <= 1 - x0.lb.  Inner: x0 >= 1 - x1.ub, x1 >= 1 - x0.ub.
    const IntervalVector x = x_out;
    x_out[0] &= Interval(-rounding::kInf, (Interval(1.0) - Interval(x[1].lb())).ub());
    x_out[1] &= Interval(-rounding::kInf, (Interval(1.0) - Interval(x[0].lb())).ub());
    if (x_out.is_empty()) x_out.set_empty();
    x_in[0] &= Interval((Interval(1.0) - Interval(x[1].ub())).lb(), rounding::kInf);
    x_in[1] &= Interval((Interval(1.0) - Interval(x[0].ub())).lb(), rounding::kInf);
    if (x_in.is_empty()) x_in.set_empty();
  };
  auto p = sivia_separator(box(0, 2, 0, 2), sep, 0.05);
  expect_well_formed(p);
  EXPECT_GT(p.count(PavingTag::Inner), 0u);
  EXPECT_GT(p.count(PavingTag::Outside), 0u);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 2);
  for (int k = 0; k < 20000; ++k) {
    const double x = u(rng), y = u(rng);
    const auto t = *p.tag_at({x, y});
    const Interval s = Interval(x) + Interval(y);
    if (s.ub() < 1) {
      EXPECT_NE(t, PavingTag::Outside);
    }
    if (s.lb() > 1) {
      EXPECT_NE(t, PavingTag::Inner);
    }
  }
  EXPECT_NEAR(p.volume(PavingTag::Inner), 0.5, 0.1);
  EXPECT_NEAR(p.volume(PavingTag::Outside), 3.5, 0.1);
}

TEST(Sivia, CtcAndSepObjects) {
  struct HalfPlane : Ctc {  // x0 <= 0.5
    HalfPlane() : Ctc(2) {}
    void contract(IntervalVector& x) const override {
      x[0] &= Interval(-rounding::kInf, 0.5);
      if (x.is_empty()) x.set_empty();
    }
  };
  struct HalfPlaneSep : Sep {
    HalfPlaneSep() : Sep(2) {}
    void separate(IntervalVector& x_in, IntervalVector& x_out) const override {
      x_out[0] &= Interval(-rounding::kInf, 0.5);
      if (x_out.is_empty()) x_out.set_empty();
      x_in[0] &= Interval(0.5, rounding::kInf);
      if (x_in.is_empty()) x_in.set_empty();
    }
  };
  auto p = sivia(box(0, 1, 0, 1), HalfPlane(), 0.1);
  EXPECT_EQ(p.outside(), std::vector<IntervalVector>{box(0.5, 1, 0, 1)});
  EXPECT_EQ(p.hull(), box(0, 0.5, 0, 1));
  auto q = sivia(box(0, 1, 0, 1), HalfPlaneSep(), 0.1);
  EXPECT_EQ(q.outside(), std::vector<IntervalVector>{box(0.5, 1, 0, 1)});
  EXPECT_EQ(q.inner(), std::vector<IntervalVector>{box(0, 0.5, 0, 1)});
  EXPECT_EQ(q.volume(PavingTag::Boundary), 0.0);  // the line x0 = 0.5, of zero area
  EXPECT_THROW(sivia(IntervalVector(3, Interval(0, 1)), HalfPlane(), 0.1), DimensionError);
  EXPECT_THROW(sivia(IntervalVector(3, Interval(0, 1)), HalfPlaneSep(), 0.1), DimensionError);
}

TEST(KernelSivia, IntervalQuadratic) {
  // [f](x) = x^2 - 1 + [-0.1, 0.1]: f- = x^2 - 1.1, f+ = x^2 - 0.9, ker = {0.9 <= x^2 <= 1.1}.
  auto f = [](const IntervalVector& x) {
    const Interval s = sqr(x[0]);
    return std::pair{IntervalVector{s - Interval(1.1)}, IntervalVector{s - Interval(0.9)}};
  };
  const double eps = 0.001;
  auto p = kernel_sivia(IntervalVector{Interval(-2, 2)}, f, eps);
  expect_well_formed(p);
  for (const auto& b : p.inner()) {
    const Interval s = sqr(b[0]);
    EXPECT_TRUE(s.lb() >= 0.9 - 1e-15 && s.ub() <= 1.1 + 1e-15) << b;
  }
  for (const auto& b : p.outside()) {
    const Interval s = sqr(b[0]);
    EXPECT_TRUE(s.ub() <= 0.9 + 1e-15 || s.lb() >= 1.1 - 1e-15) << b;
  }
  const double kernel = 2 * (std::sqrt(1.1) - std::sqrt(0.9));
  EXPECT_LT(p.volume(PavingTag::Inner), kernel);
  EXPECT_GT(p.outer_volume(), kernel);
  EXPECT_LT(p.outer_volume() - p.volume(PavingTag::Inner), 4 * eps);
  auto comps = p.components();
  ASSERT_EQ(comps.size(), 2u);
  EXPECT_TRUE(comps[0].hull[0].contains(-1.0));
  EXPECT_TRUE(comps[1].hull[0].contains(1.0));
  EXPECT_TRUE(comps[1].hull[0].contains(std::sqrt(0.9) + 1e-6) && comps[1].hull[0].contains(std::sqrt(1.1) - 1e-6));
}

TEST(KernelSivia, VectorKernelAndDimensionErrors) {
  // [f](x) = (x0 - x1 + [-0.05, 0.05], x0 + x1 - 1 + [-0.05, 0.05]): a small diamond around (0.5, 0.5).
  auto f = [](const IntervalVector& x) {
    const Interval a = x[0] - x[1], b = x[0] + x[1] - Interval(1.0);
    return std::pair{IntervalVector{a - Interval(0.05), b - Interval(0.05)},
                     IntervalVector{a + Interval(0.05), b + Interval(0.05)}};
  };
  auto p = kernel_sivia(box(0, 1, 0, 1), f, 0.01);
  EXPECT_TRUE(*p.tag_at({0.5, 0.5}) == PavingTag::Inner);
  EXPECT_TRUE(p.hull().is_subset(box(0.4, 0.6, 0.4, 0.6)));
  EXPECT_EQ(p.components().size(), 1u);
  auto bad = [](const IntervalVector& x) { return std::pair{x, IntervalVector{x[0]}}; };
  EXPECT_THROW(kernel_sivia(box(0, 1, 0, 1), bad, 0.1), DimensionError);
}

TEST(Sivia, InvalidInput) {
  auto id = [](const IntervalVector& x) { return x; };
  const IntervalVector x0 = box(0, 1, 0, 1);
  EXPECT_THROW(sivia(x0, id, box(0, 1, 0, 1), 0.0), Error);
  EXPECT_THROW(sivia(x0, id, box(0, 1, 0, 1), -1.0), Error);
  EXPECT_THROW(sivia(x0, id, box(0, 1, 0, 1), std::nan("")), Error);
  EXPECT_THROW(sivia(x0, id, Interval(0, 1), 0.1), DimensionError);  // f is 2-D, Y is 1-D
  EXPECT_THROW(sivia(IntervalVector{Interval(0, 1), Interval::pos_reals()}, id, box(0, 1, 0, 1), 0.1), Error);
  EXPECT_THROW(sivia(IntervalVector(), id, IntervalVector(), 0.1), DimensionError);
  EXPECT_THROW(sivia(x0, InclusionFunction(), box(0, 1, 0, 1), 0.1), Error);
  try {
    sivia(x0, id, box(0, 1, 0, 1), 0.0);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("eps"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("sivia"), std::string::npos);
  }
  // An empty initial box is a result: an empty paving.
  auto p = sivia(IntervalVector::empty(2), id, box(0, 1, 0, 1), 0.1);
  EXPECT_TRUE(p.is_empty());
  EXPECT_EQ(p.nb_leaves(), 0u);
  EXPECT_TRUE(p.hull().is_empty());
  EXPECT_TRUE(p.components().empty());
  EXPECT_FALSE(p.tag_at({0.5, 0.5}).has_value());
}

TEST(Sivia, TinyEpsStopsAtUnsplittableBoxes) {
  const double a = 1.0, b = std::nextafter(1.0, 2.0);
  auto p = sivia(IntervalVector{Interval(a, b)}, [](const IntervalVector& x) { return x; }, Interval(1.0),
                 1e-300);
  EXPECT_LE(p.nb_nodes(), 3u);
  EXPECT_FALSE(p.outer().empty());
}

TEST(Sivia, DeepTreesDoNotExhaustTheStack) {
  // Bisecting [-1e300, 1e300]^8 down to unsplittable boxes around a point:
  // a path of about 8 x 1050 bisections.
  const double third = 1.0 / 3.0;
  auto p = sivia(IntervalVector(8, Interval(-1e300, 1e300)), [](const IntervalVector& x) { return x; },
                 IntervalVector(8, Interval(third)), 1e-300);
  const auto outer = p.outer();
  ASSERT_FALSE(outer.empty());
  for (const auto& b : outer) {
    EXPECT_TRUE(b.contains(Vector(8, third)));
    EXPECT_LE(b.max_diam(), 1e-16);
  }
  EXPECT_GT(p.nb_nodes(), 16000u);
}

TEST(Sivia, ExceptionsOfWorkerThreadsReachTheCaller) {
  auto f = [](const IntervalVector& x) -> IntervalVector {
    if (x[0].ub() <= -0.5 && x[1].ub() <= -0.5) throw DimensionError("test: thrown from f");
    return IntervalVector{sqr(x[0]) + sqr(x[1])};
  };
  EXPECT_THROW(sivia(box(-1, 1, -1, 1), f, Interval(0, 1), 0.01), DimensionError);
  auto bad = [](IntervalVector& x_in, IntervalVector&) { x_in = IntervalVector(3); };
  EXPECT_THROW(sivia_separator(box(-1, 1, -1, 1), bad, 0.01), DimensionError);
}

TEST(Sivia, ResultDoesNotDependOnTheThreadCount) {
  auto f = [](const IntervalVector& x) {
    return IntervalVector{sqrt(sqr(x[0] - Interval(8.0)) + sqr(x[1] - Interval(5.0))),
                          sqrt(sqr(x[0] - Interval(7.0)) + sqr(x[1] - Interval(2.2)))};
  };
  const IntervalVector y = box(9.03, 9.83, 6.94, 7.74);
  auto run = [&](std::size_t threads, bool parallel) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return sivia(box(-10, 10, -10, 10), f, y, 0.02, SiviaOptions{parallel, {}});
  };
  const Paving one = run(1, true), two = run(2, true), seq = run(2, false), four = run(4, true);
  EXPECT_GT(one.nb_nodes(), 1000u);
  EXPECT_TRUE(one == two);
  EXPECT_TRUE(one == seq);
  EXPECT_TRUE(one == four);
  EXPECT_EQ(one.outer(), two.outer());
  // The robot (0, 0) is in the solution set.
  EXPECT_NE(*one.tag_at({0.0, 0.0}), PavingTag::Outside);
  // Two beacons leave an ambiguity: a second large component, far from the robot.
  const auto comps = one.components();
  ASSERT_GE(comps.size(), 2u);
  EXPECT_TRUE(comps[0].hull.contains({0.0, 0.0}));
  EXPECT_TRUE(comps.back().hull.contains({8.0, -4.5}));
}
