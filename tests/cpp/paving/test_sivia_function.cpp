// SIVIA over expression Functions and the CtcFunction/SepFunction of the ctc
// layer: the two-beacon problem of thesis Table 2.2 and domain subtleties.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <random>

#include "sillage/ctc/ctc_algebra.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/sep_algebra.h"
#include "sillage/ctc/sep_function.h"
#include "sillage/paving/sivia_function.h"

using namespace sillage;

namespace {

IntervalVector box(double a, double b, double c, double d) { return {Interval(a, b), Interval(c, d)}; }

const Function kRanges({"x1", "x2"}, "(sqrt((x1 - 8)^2 + (x2 - 5)^2), sqrt((x1 - 7)^2 + (x2 - 2.2)^2))");
const IntervalVector kY = box(9.03, 9.83, 6.94, 7.74);
const IntervalVector kX0 = box(-10, 10, -10, 10);

// Is p surely in (1) or surely out of (-1) the two-beacon set? 0: undecided.
int classify(double x, double y) {
  const IntervalVector r = kRanges.eval_vector(IntervalVector::from_point({x, y}));
  if (r.is_subset(kY)) return 1;
  if (!r.intersects(kY)) return -1;
  return 0;
}

void expect_guaranteed(const Paving& p, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int k = 0; k < 20000; ++k) {
    const double x = u(rng), y = u(rng);
    const auto t = p.tag_at({x, y});
    ASSERT_TRUE(t.has_value());
    const int c = classify(x, y);
    if (c == 1) {
      EXPECT_NE(*t, PavingTag::Outside) << x << " " << y;
    }
    if (c == -1) {
      EXPECT_NE(*t, PavingTag::Inner) << x << " " << y;
    }
  }
}

}  // namespace

TEST(SiviaFunction, TwoBeaconsPlain) {
  auto p = sivia(kX0, kRanges, kY, 0.05);
  EXPECT_GT(p.count(PavingTag::Inner), 0u);
  EXPECT_NE(*p.tag_at({0.0, 0.0}), PavingTag::Outside);  // the robot
  expect_guaranteed(p, 11);
  // Same natural inclusion function as a lambda: same guarantees, close volumes.
  auto q = sivia(kX0, [](const IntervalVector& x) { return kRanges.eval_vector(x); }, kY, 0.05);
  EXPECT_EQ(p, q);  // f is total here, so the definition check changes nothing
}

TEST(SiviaFunction, TwoBeaconsWithSeparators) {
  const SepInter both({std::make_shared<SepFunction>(kRanges[0], kY[0]),
                       std::make_shared<SepFunction>(kRanges[1], kY[1])});
  auto p = sivia(kX0, both, 0.05);
  auto plain = sivia(kX0, kRanges, kY, 0.05);
  expect_guaranteed(p, 12);
  EXPECT_LT(p.nb_leaves(), plain.nb_leaves());
  EXPECT_NE(*p.tag_at({0.0, 0.0}), PavingTag::Outside);
  EXPECT_NEAR(p.volume(PavingTag::Inner), plain.volume(PavingTag::Inner), 0.3 * plain.volume(PavingTag::Inner));
  // Deterministic whatever the thread count.
  Paving one, two;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = sivia(kX0, both, 0.05);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = sivia(kX0, both, 0.05);
  }
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, p);
}

TEST(SiviaFunction, TwoBeaconsWithContractors) {
  const CtcFunction c1(kRanges[0], kY[0]), c2(kRanges[1], kY[1]);
  auto both = [&](IntervalVector& x) {
    c1.contract(x);
    c2.contract(x);
  };
  auto p = sivia_contractor(kX0, both, 0.05);
  EXPECT_EQ(p.count(PavingTag::Inner), 0u);
  expect_guaranteed(p, 13);
  auto plain = sivia(kX0, kRanges, kY, 0.05);
  // The outer approximation is in the plain one's, up to the eps-wide fringe.
  EXPECT_TRUE(p.hull().is_subset(plain.hull().inflate(0.05)));
}

TEST(SiviaFunction, TwoBeaconsTestThenContract) {
  // Fig. 2.13: the inclusion test of Alg. 1, then a contraction before bisecting.
  const CtcInter ctc({std::make_shared<CtcFunction>(kRanges[0], kY[0]),
                      std::make_shared<CtcFunction>(kRanges[1], kY[1])});
  auto p = sivia(kX0, kRanges, kY, ctc, 0.05);
  auto plain = sivia(kX0, kRanges, kY, 0.05);
  expect_guaranteed(p, 14);
  EXPECT_LT(p.nb_leaves(), plain.nb_leaves());
  EXPECT_GT(p.count(PavingTag::Inner), 0u);
  EXPECT_LT(p.outer_volume(), plain.outer_volume());
  // The callable form gives the same paving (f is total: no definition issue).
  auto q = sivia(
      kX0, [](const IntervalVector& x) { return kRanges.eval_vector(x); }, kY,
      [&ctc](IntervalVector& x) { ctc.contract(x); }, 0.05);
  EXPECT_EQ(p, q);
  EXPECT_THROW(sivia(IntervalVector(3, Interval(0, 1)), kRanges, kY, ctc, 0.05), DimensionError);
}

TEST(SiviaFunction, InnerRequiresTheFunctionToBeDefined) {
  const Function f({"x"}, "sqrt(x)");
  // Set-based evaluation: sqrt([-1, 1]) = [0, 1] is in Y, yet -0.5 is not in f^-1(Y).
  auto p = sivia(IntervalVector{Interval(-1, 1)}, f, Interval(0, 2), 0.01);
  EXPECT_EQ(*p.tag_at({0.5}), PavingTag::Inner);
  EXPECT_EQ(*p.tag_at({-0.5}), PavingTag::Outside);
  EXPECT_LT(p.volume(PavingTag::Boundary), 0.02);
  for (const auto& b : p.inner()) EXPECT_GE(b[0].lb(), 0.0);
}

TEST(SiviaFunction, KernelOfAnIntervalFunction) {
  // [f](x) = x^2 - 1 + [-0.1, 0.1]
  const Function lo({"x"}, "x^2 - 1.1"), hi({"x"}, "x^2 - 0.9");
  auto p = kernel_sivia(IntervalVector{Interval(-2, 2)}, lo, hi, 0.001);
  const double kernel = 2 * (std::sqrt(1.1) - std::sqrt(0.9));
  EXPECT_LT(p.volume(PavingTag::Inner), kernel);
  EXPECT_GT(p.outer_volume(), kernel);
  EXPECT_EQ(p.components().size(), 2u);
  // Bounds defined only for x >= 0: no inner box may contain negatives.
  const Function lo2({"x"}, "sqrt(x) - 1.1"), hi2({"x"}, "sqrt(x) - 0.9");
  auto q = kernel_sivia(IntervalVector{Interval(-2, 2)}, lo2, hi2, 0.001);
  for (const auto& b : q.inner()) EXPECT_GE(b[0].lb(), 0.0);
  EXPECT_EQ(*q.tag_at({1.0}), PavingTag::Inner);
}

TEST(SiviaFunction, DimensionErrors) {
  EXPECT_THROW(sivia(IntervalVector(3, Interval(0, 1)), kRanges, kY, 0.1), DimensionError);
  EXPECT_THROW(sivia(kX0, kRanges, Interval(0, 1), 0.1), DimensionError);
  const Function lo({"x"}, "x"), hi2({"x", "y"}, "x + y");
  EXPECT_THROW(kernel_sivia(IntervalVector{Interval(0, 1)}, lo, hi2, 0.1), DimensionError);
  EXPECT_THROW(sivia(kX0, kRanges, kY, 0.0), Error);
}
