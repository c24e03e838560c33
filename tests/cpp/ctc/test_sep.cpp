// Separators: hand cases for SepFunction, SepCtcPair and the algebra, and the
// separator laws on random boxes: a point removed by the outer part is never
// in X, a point removed by the inner part is always in X. Membership of a
// sample point is decided by a reference (the natural evaluation at the point
// and an explicit domain test); undecided points are skipped.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <vector>

#include "ctc/ctc_test_util.h"
#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/sep_algebra.h"
#include "sillage/ctc/sep_ctc_pair.h"
#include "sillage/ctc/sep_function.h"

using namespace sillage;
using sillage::test::kInf;
using sillage::test::random_around;

namespace {

std::shared_ptr<SepFunction> disk(double cx, double cy, double r) {
  const Function f({"x", "y"}, "(x - " + std::to_string(cx) + ")^2 + (y - " + std::to_string(cy) + ")^2");
  return std::make_shared<SepFunction>(f, Interval(-kInf, r * r));  // f >= 0 anyway
}

}  // namespace

TEST(SepFunction, DiskHandCases) {
  const auto s = disk(0, 0, 1);
  IntervalVector in{{-0.5, 0.5}, {-0.5, 0.5}}, out(in);
  s->separate(in, out);
  EXPECT_TRUE(in.is_empty());  // proven inside
  EXPECT_EQ(out, (IntervalVector{{-0.5, 0.5}, {-0.5, 0.5}}));

  IntervalVector in2{{2, 3}, {2, 3}}, out2(in2);
  s->separate(in2, out2);
  EXPECT_EQ(in2, (IntervalVector{{2, 3}, {2, 3}}));
  EXPECT_TRUE(out2.is_empty());  // proven outside

  IntervalVector in3{{0.5, 1.5}, {-0.1, 0.1}}, out3(in3);
  s->separate(in3, out3);
  EXPECT_LT(out3[0].ub(), 1.01);  // cut by the outer part
  EXPECT_GT(in3[0].lb(), 0.98);   // cut by the inner part (points with x < 0.98 are inside)
  EXPECT_TRUE(in3.contains({1.2, 0}) && out3.contains({0.9, 0}));
}

TEST(SepFunction, AllRealsAndEmptyImages) {
  const Function f({"x"}, "x^2");
  IntervalVector in{{-3, 3}}, out(in);
  SepFunction(f, Interval()).separate(in, out);  // X = R
  EXPECT_TRUE(in.is_empty());
  EXPECT_EQ(out[0], Interval(-3, 3));
  IntervalVector in2{{-3, 3}}, out2(in2);
  SepFunction(f, Interval::empty()).separate(in2, out2);  // X = ∅
  EXPECT_EQ(in2[0], Interval(-3, 3));
  EXPECT_TRUE(out2.is_empty());
}

TEST(SepFunction, PartialFunctionsNeverClaimUndefinedPoints) {
  // X = { x : sqrt(x) defined } = [0, inf): [-4, -1] is outside although the
  // set-based image sqrt([-4, -1]) is empty and "fits" any [y].
  const Function f({"x"}, "sqrt(x)");
  IntervalVector in{{-4, 4}}, out(in);
  SepFunction(f, Interval()).separate(in, out);
  EXPECT_TRUE(in.contains({-2}));
  EXPECT_EQ(out[0], Interval(0, 4));
  IntervalVector in2{{1, 4}}, out2(in2);
  SepFunction(f, Interval()).separate(in2, out2);
  EXPECT_TRUE(in2.is_empty());  // defined there: proven inside
  // log(x) ∈ [0, 1], X = [1, e]: [-1, 0] must never be claimed.
  const Function g({"x"}, "log(x)");
  IntervalVector in3{{-1, 2}}, out3(in3);
  SepFunction(g, Interval(0, 1)).separate(in3, out3);
  EXPECT_TRUE(in3.contains({-0.5}));
  EXPECT_TRUE(out3.contains({1.5}) && !out3.contains({0.5}));
  IntervalVector in4{{0.5, 2}}, out4(in4);
  SepFunction(g, Interval(0, 1)).separate(in4, out4);
  EXPECT_EQ(in4[0].lb(), 0.5);  // log(x) <= 0 there: not proven in X
  EXPECT_GE(in4[0].ub(), 1.0);  // [1, 2] proven in X and defined: the cut is kept
  EXPECT_LT(in4[0].ub(), 1.0 + 1e-12);
}

TEST(SepAlgebra, CtcPairNotInterUnion) {
  const auto a = std::make_shared<CtcBox>(IntervalVector{{0, 1}});
  const auto b = std::make_shared<CtcBox>(IntervalVector{{2, 3}});
  const auto pair = std::make_shared<SepCtcPair>(a, b);
  IntervalVector in{{-5, 5}}, out(in);
  pair->separate(in, out);
  EXPECT_EQ(in[0], Interval(0, 1));
  EXPECT_EQ(out[0], Interval(2, 3));
  IntervalVector nin{{-5, 5}}, nout(nin);
  (~pair)->separate(nin, nout);
  EXPECT_EQ(nin[0], Interval(2, 3));
  EXPECT_EQ(nout[0], Interval(0, 1));

  // Two disks: (0,0) and (1,0), radius 1.
  const auto d1 = disk(0, 0, 1), d2 = disk(1, 0, 1);
  IntervalVector i_in{{-0.3, -0.2}, {-0.1, 0.1}}, i_out(i_in);  // in d1 only
  (d1 & d2)->separate(i_in, i_out);
  EXPECT_TRUE(i_out.is_empty());
  IntervalVector u_in(i_in = IntervalVector{{-0.3, -0.2}, {-0.1, 0.1}}), u_out(u_in);
  (d1 | d2)->separate(u_in, u_out);
  EXPECT_TRUE(u_in.is_empty());
  EXPECT_EQ(u_out, i_in);
  EXPECT_THROW(SepInter({d1, std::make_shared<SepCtcPair>(a, a)}), DimensionError);
  EXPECT_THROW(SepCtcPair(a, std::make_shared<CtcBox>(IntervalVector(2))), DimensionError);
  EXPECT_THROW(SepUnion({}), Error);
  IntervalVector wrong(3), ok(2);
  EXPECT_THROW(d1->separate(wrong, ok), DimensionError);
}

namespace {

struct SepCase {
  std::shared_ptr<const Sep> sep;
  // +1 certainly in X, -1 certainly out, 0 undecided.
  std::function<int(const Vector&)> member;
};

// Membership of p in { x : f(x) defined and f(x) ∈ y }, `defined` deciding the first part.
std::function<int(const Vector&)> membership(const Function& f, const IntervalVector& y,
                                             std::function<bool(const Vector&)> defined) {
  return [=](const Vector& p) {
    if (!defined(p)) return -1;
    const IntervalVector v = f.eval_vector(IntervalVector::from_point(p));
    if (v.is_subset(y)) return 1;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!v[i].intersects(y[i])) return -1;
    }
    return 0;
  };
}

}  // namespace

TEST(SepLaws, RemovedPointsAreClassifiedCorrectly) {
  const auto always = [](const Vector&) { return true; };
  std::vector<SepCase> cases;
  {
    const Function f({"x", "y"}, "x^2 + y^2 - x * y + sin(3 * x)");
    const IntervalVector y{{0.5, 4}};
    cases.push_back({std::make_shared<SepFunction>(f, y), membership(f, y, always)});
  }
  {
    const Function f({"x", "y"}, "(x + y, x - y^3)");
    const IntervalVector y{{-1, 2}, {0, kInf}};
    cases.push_back({std::make_shared<SepFunction>(f, y), membership(f, y, always)});
  }
  {
    const Function f({"x", "y"}, "sqrt(x) + log(y + 2)");
    const IntervalVector y{{-kInf, 2}};
    cases.push_back({std::make_shared<SepFunction>(f, y),
                     membership(f, y, [](const Vector& p) { return p[0] >= 0 && p[1] > -2; })});
  }
  {
    const Function f({"x", "y"}, "x / y");
    const IntervalVector y{{-1, 1}};
    cases.push_back(
        {std::make_shared<SepFunction>(f, y), membership(f, y, [](const Vector& p) { return p[1] != 0; })});
  }
  {
    // Intersection, union and complement of two disks.
    const Function f1({"x", "y"}, "x^2 + y^2"), f2({"x", "y"}, "(x - 1)^2 + y^2");
    const IntervalVector r{{-kInf, 1}};
    const auto s1 = std::make_shared<SepFunction>(f1, r), s2 = std::make_shared<SepFunction>(f2, r);
    const auto m1 = membership(f1, r, always), m2 = membership(f2, r, always);
    cases.push_back({s1 & s2, [=](const Vector& p) { return std::min(m1(p), m2(p)); }});
    cases.push_back({s1 | s2, [=](const Vector& p) { return std::max(m1(p), m2(p)); }});
    cases.push_back({~s1, [=](const Vector& p) { return -m1(p); }});
  }
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-3, 3), unit(0, 1);
  int removed_in = 0, removed_out = 0;
  for (const auto& c : cases) {
    for (int trial = 0; trial < 300; ++trial) {
      IntervalVector x(2);
      for (std::size_t i = 0; i < 2; ++i) {
        const double a = u(rng), w = 3 * unit(rng) * unit(rng);
        x[i] = Interval(a, a + w);
      }
      IntervalVector in(x), out(x);
      c.sep->separate(in, out);
      ASSERT_TRUE(in.is_subset(x) && out.is_subset(x));
      for (int s = 0; s < 40; ++s) {
        const Vector p{x[0].lb() + x[0].diam() * unit(rng), x[1].lb() + x[1].diam() * unit(rng)};
        if (!x.contains(p)) continue;
        const int m = c.member(p);
        if (!out.contains(p)) {
          ++removed_out;
          ASSERT_NE(m, 1) << c.sep->name() << ": outer part removed (" << p[0] << ", " << p[1] << ") of X from " << x;
        }
        if (!in.contains(p)) {
          ++removed_in;
          ASSERT_NE(m, -1) << c.sep->name() << ": inner part removed (" << p[0] << ", " << p[1] << ") not in X from "
                           << x;
        }
      }
    }
  }
  EXPECT_GT(removed_in, 1000);
  EXPECT_GT(removed_out, 1000);
}
