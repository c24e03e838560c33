// Primitive contractors: CtcBox, CtcBinary (C+ of (2.31), ...), CtcUnary
// (C_exp of (2.32), ...). Hand cases, then the contractor laws on random boxes
// around a true solution whose exact value MPFR encloses.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "ctc/ctc_test_util.h"
#include "sillage/ctc/ctc_binary.h"
#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/ctc_unary.h"

using namespace sillage;
using sillage::test::kInf;
using sillage::test::mpfr_enclosure;
using sillage::test::random_around;

TEST(CtcBox, IntersectsWithTheBox) {
  CtcBox c(IntervalVector{{0, 2}, {-1, 1}});
  IntervalVector x{{1, 5}, {-3, 0}};
  c.contract(x);
  EXPECT_EQ(x, (IntervalVector{{1, 2}, {-1, 0}}));
  IntervalVector far{{3, 4}, {0, 0}};
  c.contract(far);
  EXPECT_TRUE(far.is_empty());
  EXPECT_TRUE(far[1].is_empty());  // the whole box is set empty
  IntervalVector bad(3);
  EXPECT_THROW(c.contract(bad), DimensionError);
}

TEST(CtcBinary, ThesisExampleOfCPlus) {
  // C+([4,5],[0,3],[-2,2]) = ([4,5],[2,3],[1,2]), box (a, x, y) with a = x + y (2.31).
  IntervalVector b{{4, 5}, {0, 3}, {-2, 2}};
  CtcAdd().contract(b);
  EXPECT_EQ(b, (IntervalVector{{4, 5}, {2, 3}, {1, 2}}));
}

TEST(CtcBinary, HandCases) {
  IntervalVector m{Interval(), {2, 3}, {4, 5}};
  CtcMul().contract(m);
  EXPECT_EQ(m[0], Interval(8, 15));
  IntervalVector m2{{1, 2}, Interval(), {1, 2}};
  CtcMul().contract(m2);
  EXPECT_EQ(m2[1], Interval(0.5, 2));
  IntervalVector s{{0, 0}, {1, 3}, {2, 5}};
  CtcSub().contract(s);
  EXPECT_EQ(s, (IntervalVector{{0, 0}, {2, 3}, {2, 3}}));
  IntervalVector d{{2, 2}, Interval(), {1, 3}};
  CtcDiv().contract(d);
  EXPECT_EQ(d[1], Interval(2, 6));
  IntervalVector none{{1, 1}, {0, 0}, Interval()};  // 0 * y = 1 has no solution
  CtcMul().contract(none);
  EXPECT_TRUE(none.is_empty());
  for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(none[i].is_empty());
  IntervalVector mx{{-1, 4}, {0, 1}, {-5, 10}};  // z = max(x, y)
  CtcBinary("max").contract(mx);
  EXPECT_EQ(mx, (IntervalVector{{0, 4}, {0, 1}, {-5, 4}}));
}

TEST(CtcBinary, NamesAndErrors) {
  EXPECT_EQ(CtcBinary("add").op(), BinaryOp::add);
  EXPECT_EQ(CtcBinary("atan2").name(), "CtcBinary(atan2)");
  EXPECT_THROW(CtcBinary("plus"), Error);
  IntervalVector two(2);
  try {
    CtcAdd().contract(two);
    FAIL() << "no DimensionError";
  } catch (const DimensionError& e) {
    EXPECT_NE(std::string(e.what()).find("CtcBinary(add)"), std::string::npos) << e.what();
  }
}

TEST(CtcUnary, ThesisExampleOfCExp) {
  // C_exp on (a, b) with a = exp(b) (2.32): a ∩= exp(b), b ∩= log(a).
  IntervalVector x{{-kInf, 1}, Interval()};
  CtcUnary("exp").contract(x);
  EXPECT_EQ(x[0].lb(), 0.0);
  EXPECT_EQ(x[0].ub(), 1.0);
  EXPECT_EQ(x[1].lb(), -kInf);
  EXPECT_GE(x[1].ub(), 0.0);
  EXPECT_LE(x[1].ub(), 1e-15);
}

TEST(CtcUnary, HandCases) {
  IntervalVector sq{{4, 9}, Interval()};
  CtcUnary(UnaryOp::sqr).contract(sq);
  EXPECT_EQ(sq[1], Interval(-3, 3));  // hull of [-3,-2] and [2,3]
  IntervalVector sq_pos{{4, 9}, {0, kInf}};
  CtcUnary(UnaryOp::sqr).contract(sq_pos);
  EXPECT_EQ(sq_pos[1], Interval(2, 3));
  IntervalVector rt{{2, 3}, Interval()};
  CtcUnary("sqrt").contract(rt);
  EXPECT_EQ(rt[1], Interval(4, 9));
  IntervalVector cube{{8, 27}, Interval()};
  CtcUnary("pow", 3).contract(cube);
  EXPECT_TRUE(cube[1].contains(2) && cube[1].contains(3));
  EXPECT_LT(cube[1].diam(), 1 + 1e-12);
  IntervalVector neg_sqrt{{-2, -1}, Interval()};  // sqrt(x) is never negative
  CtcUnary("sqrt").contract(neg_sqrt);
  EXPECT_TRUE(neg_sqrt.is_empty());
  EXPECT_EQ(CtcUnary("root", 3).name(), "CtcUnary(root, 3)");
  EXPECT_THROW(CtcUnary("root", 0), Error);
  EXPECT_THROW(CtcUnary("erf"), Error);
  IntervalVector three(3);
  EXPECT_THROW(CtcUnary("exp").contract(three), DimensionError);
}

// ---- contractor laws on random boxes around a true solution ----

namespace {

using MpfrOp = std::function<void(mpfr_ptr, mpfr_ptr, mpfr_ptr, mpfr_rnd_t)>;

struct BinaryCase {
  const char* name;
  double x_lo, x_hi, y_lo, y_hi;                 // where the solution point is drawn
  int (*op)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);
};

struct UnaryCase {
  const char* name;
  int n;
  double x_lo, x_hi;
  std::function<void(mpfr_ptr, mpfr_ptr, mpfr_rnd_t)> op;
};

// Checks contraction and that the solution (v, x, y) with v exactly in [v_enc] is kept.
void check_laws(const Ctc& c, const IntervalVector& box, const std::vector<double>& point, const Interval& v_enc) {
  IntervalVector out(box);
  c.contract(out);
  ASSERT_TRUE(out.is_subset(box)) << c.name() << " enlarged " << box << " to " << out;
  ASSERT_FALSE(out.is_empty()) << c.name() << " lost the solution in " << box;
  ASSERT_TRUE(v_enc.is_subset(out[0])) << c.name() << " lost " << v_enc << " from " << box << " -> " << out;
  for (std::size_t i = 0; i < point.size(); ++i) {
    ASSERT_TRUE(out[i + 1].contains(point[i])) << c.name() << " lost " << point[i] << " from " << box << " -> " << out;
  }
}

}  // namespace

TEST(CtcBinary, ContractionAndConsistencyOnRandomBoxes) {
  const BinaryCase cases[] = {
      {"add", -5, 5, -5, 5, mpfr_add},      {"sub", -5, 5, -5, 5, mpfr_sub},
      {"mul", -5, 5, -5, 5, mpfr_mul},      {"div", -5, 5, 0.1, 5, mpfr_div},
      {"div", -5, 5, -5, -0.1, mpfr_div},   {"min", -5, 5, -5, 5, mpfr_min},
      {"max", -5, 5, -5, 5, mpfr_max},      {"atan2", -5, 5, -5, 5, mpfr_atan2},
      {"pow", 0.1, 5, -3, 3, mpfr_pow},
  };
  std::mt19937_64 rng(12345);
  for (const auto& k : cases) {
    const CtcBinary c(k.name);
    std::uniform_real_distribution<double> ux(k.x_lo, k.x_hi), uy(k.y_lo, k.y_hi);
    for (int trial = 0; trial < 3000; ++trial) {
      // Half of the points on a coarse grid, where exact results and ties happen.
      double x = ux(rng), y = uy(rng);
      if (trial % 2) {
        x = std::round(x * 4) / 4;
        y = std::round(y * 4) / 4;
        if (!(x >= k.x_lo && x <= k.x_hi && y >= k.y_lo && y <= k.y_hi)) continue;
      }
      x += 0.0;  // no -0: MPFR's atan2(-0, x < 0) = -pi is not the real atan2
      y += 0.0;
      const Interval v = mpfr_enclosure([&](mpfr_ptr r, mpfr_ptr a, mpfr_ptr b, mpfr_rnd_t m) {
        mpfr_set_d(a, x, MPFR_RNDN);
        mpfr_set_d(b, y, MPFR_RNDN);
        k.op(r, a, b, m);
      });
      const IntervalVector box{random_around(v.lb(), v.ub(), rng), random_around(x, rng), random_around(y, rng)};
      check_laws(c, box, {x, y}, v);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}

TEST(CtcUnary, ContractionAndConsistencyOnRandomBoxes) {
  using R = mpfr_rnd_t;
  const UnaryCase cases[] = {
      {"neg", 0, -5, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_neg(r, a, m); }},
      {"sqr", 0, -5, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_sqr(r, a, m); }},
      {"sqrt", 0, 0, 9, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_sqrt(r, a, m); }},
      {"exp", 0, -5, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_exp(r, a, m); }},
      {"log", 0, 1e-3, 20, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_log(r, a, m); }},
      {"sin", 0, -10, 10, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_sin(r, a, m); }},
      {"cos", 0, -10, 10, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_cos(r, a, m); }},
      {"tan", 0, -1.5, 1.5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_tan(r, a, m); }},
      {"asin", 0, -1, 1, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_asin(r, a, m); }},
      {"acos", 0, -1, 1, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_acos(r, a, m); }},
      {"atan", 0, -10, 10, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_atan(r, a, m); }},
      {"sinh", 0, -5, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_sinh(r, a, m); }},
      {"cosh", 0, -5, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_cosh(r, a, m); }},
      {"tanh", 0, -5, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_tanh(r, a, m); }},
      {"abs", 0, -5, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_abs(r, a, m); }},
      {"sign", 0, -2, 2, [](mpfr_ptr r, mpfr_ptr a, R) { mpfr_set_si(r, mpfr_sgn(a), MPFR_RNDN); }},
      {"pow", 3, -5, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_pow_si(r, a, 3, m); }},
      {"pow", -2, 0.1, 5, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_pow_si(r, a, -2, m); }},
      {"root", 3, -9, 9, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_rootn_ui(r, a, 3, m); }},
      {"root", 2, 0, 9, [](mpfr_ptr r, mpfr_ptr a, R m) { mpfr_rootn_ui(r, a, 2, m); }},
  };
  std::mt19937_64 rng(777);
  for (const auto& k : cases) {
    const CtcUnary c(k.name, k.n);
    std::uniform_real_distribution<double> ux(k.x_lo, k.x_hi);
    for (int trial = 0; trial < 2000; ++trial) {
      double x = ux(rng);
      if (trial % 2) {
        x = std::round(x * 4) / 4;
        if (!(x >= k.x_lo && x <= k.x_hi)) continue;
      }
      const Interval v = mpfr_enclosure([&](mpfr_ptr r, mpfr_ptr a, mpfr_ptr, mpfr_rnd_t m) {
        mpfr_set_d(a, x, MPFR_RNDN);
        k.op(r, a, m);
      });
      const IntervalVector box{random_around(v.lb(), v.ub(), rng), random_around(x, rng)};
      check_laws(c, box, {x}, v);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}
