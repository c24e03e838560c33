// HC4-revise: the thesis decomposition (2.30), the beacons of Table 2.1,
// the contractor laws on random inputs, the skipping of idle nodes and the
// batch form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sillage/expr/function.h"
#include "sillage/expr/tape.h"
#include "sillage/interval/backward.h"

using namespace sillage;

namespace {

IntervalVector all2() { return IntervalVector(2); }

// A decimal number as the real it denotes (an interval enclosing it).
Interval real(const std::string& s) { return Function(std::vector<std::string>{}, s).eval(IntervalVector(0)); }

}  // namespace

// One HC4 pass is exactly the forward-backward propagation over the
// decomposition (2.30): a = x1 - x1k, b = x2 - x2k, c = a^2, d = b^2, e = c + d, rho = sqrt(e).
TEST(Hc4, EqualsTheDecomposition230) {
  const Interval xk1 = real("-0.5"), xk2 = real("4.0"), rho0 = Interval(real("3.63").lb(), real("4.43").ub());
  Function g({"x1", "x2"}, "sqrt((x1 - -0.5)^2 + (x2 - 4.0)^2)");
  for (const IntervalVector& x0 : {all2(), IntervalVector{Interval(-1, 1), Interval(-1, 2)},
                                   IntervalVector{Interval(-6, 0), Interval(5, 9)}}) {
    // Forward.
    Interval x1 = x0[0], x2 = x0[1], k1 = xk1, k2 = xk2;
    Interval a = x1 - k1, b = x2 - k2, c = sqr(a), d = sqr(b), e = c + d, rho = sqrt(e) & rho0;
    // Backward.
    bool ok = bwd_sqrt(rho, e) && bwd_add(e, c, d) && bwd_sqr(d, b) && bwd_sqr(c, a) && bwd_sub(b, x2, k2) &&
              bwd_sub(a, x1, k1);
    IntervalVector x = x0;
    const bool hc4 = g.hc4_revise(x, IntervalVector{rho0});
    ASSERT_EQ(hc4, ok && !rho.is_empty());
    if (hc4) {
      EXPECT_EQ(x[0], x1) << x0;
      EXPECT_EQ(x[1], x2) << x0;
    }
  }
}

TEST(Hc4, Table21BeaconsFromTheWholePlane) {
  struct Beacon {
    const char* x1;
    const char* x2;
    const char* lo;
    const char* hi;
  };
  const Beacon beacons[] = {{"-0.5", "4.0", "3.63", "4.43"}, {"-2.5", "-2.5", "3.13", "3.93"},
                            {"2.5", "-0.5", "2.15", "2.95"}};
  // One beacon alone: the box of its ring, outward.
  {
    Function g({"x1", "x2"}, "sqrt((x1 + 0.5)^2 + (x2 - 4.0)^2)");
    IntervalVector x = all2();
    ASSERT_TRUE(g.hc4_revise(x, Interval(real("3.63").lb(), real("4.43").ub())));
    EXPECT_TRUE(x[0].is_superset(Interval(-4.93, 3.93)));
    EXPECT_TRUE(x[1].is_superset(Interval(-0.43, 8.43)));
    EXPECT_NEAR(x[0].lb(), -4.93, 1e-12);
    EXPECT_NEAR(x[0].ub(), 3.93, 1e-12);
    EXPECT_NEAR(x[1].lb(), -0.43, 1e-12);
    EXPECT_NEAR(x[1].ub(), 8.43, 1e-12);
  }
  // The three constraints propagated to a fixed point (thesis 2.3.3).
  std::vector<Function> gs;
  std::vector<Interval> rhos;
  for (const Beacon& b : beacons) {
    gs.emplace_back(std::vector<std::string>{"x1", "x2"},
                    std::string("sqrt((x1 - ") + b.x1 + ")^2 + (x2 - " + b.x2 + ")^2)");
    rhos.push_back(Interval(real(b.lo).lb(), real(b.hi).ub()));
  }
  IntervalVector x = all2();
  int iterations = 0;
  for (IntervalVector prev; prev != x && iterations < 100; ++iterations) {
    prev = x;
    for (std::size_t k = 0; k < 3; ++k) ASSERT_TRUE(gs[k].hc4_revise(x, rhos[k]));
  }
  EXPECT_LT(iterations, 100);
  EXPECT_TRUE(x.contains({0.0, 0.0}));  // the robot
  // Brute force: every grid point satisfying the three constraints is kept.
  for (double p1 = -6; p1 <= 6; p1 += 0.01) {
    for (double p2 = -6; p2 <= 6; p2 += 0.01) {
      bool sol = true;
      for (std::size_t k = 0; k < 3 && sol; ++k)
        sol = gs[k].eval(IntervalVector::from_point({p1, p2})).is_subset(rhos[k]);
      if (sol) {
        ASSERT_TRUE(x.contains({p1, p2})) << p1 << ", " << p2;
      }
    }
  }
  EXPECT_LT(x.max_diam(), 1.5);  // contracted far below the single rings' boxes
}

TEST(Hc4, InconsistencyEmptiesTheBox) {
  Function g({"x1", "x2"}, "x1^2 + x2^2");
  IntervalVector x = all2();
  EXPECT_FALSE(g.hc4_revise(x, Interval(-2, -1)));
  EXPECT_TRUE(x.is_empty());
  IntervalVector z{Interval(2, 3), Interval(2, 3)};
  EXPECT_FALSE(g.hc4_revise(z, Interval(0, 1)));
  EXPECT_TRUE(z.is_empty());
  IntervalVector e = IntervalVector::empty(2);
  EXPECT_FALSE(g.hc4_revise(e, Interval(0, 1)));
  Function s({"x"}, "sqrt(x)");
  IntervalVector n{Interval(-3, -1)};
  EXPECT_FALSE(s.hc4_revise(n, Interval::all_reals()));  // no point of the domain
}

TEST(Hc4, SharedNodesReceiveTheIntersectionOfProjections) {
  // x * x with x shared: bwd_mul projects twice onto the same node.
  Function f({"x"}, "x * x");
  IntervalVector x{Interval(1, 10)};
  ASSERT_TRUE(f.hc4_revise(x, Interval(4.0)));
  EXPECT_TRUE(x[0].contains(2.0));
  EXPECT_LT(x[0].ub(), 4.0 + 1e-12);
  // (x-1)^2 + (x-1)^2 = 8 with x in [0, 10]: each term in [0, 8] (the two
  // uses are projected independently), so x - 1 in [-1, sqrt(8)].
  Function g({"x"}, "(x-1)^2 + (x-1)^2");
  IntervalVector y{Interval(0, 10)};
  ASSERT_TRUE(g.hc4_revise(y, Interval(8.0)));
  EXPECT_EQ(y[0].lb(), 0.0);
  EXPECT_TRUE(y[0].contains(1 + std::sqrt(8.0)));
  EXPECT_NEAR(y[0].ub(), 1 + std::sqrt(8.0), 1e-14);
  // A vector function: both outputs contract the same variable.
  Function v({"x", "y"}, "(x + y, x - y)");
  IntervalVector b = all2();
  ASSERT_TRUE(v.hc4_revise(b, IntervalVector{Interval(0, 1), Interval(0, 1)}));
  EXPECT_TRUE(b.is_unbounded());  // one pass of HC4 cannot bound x from x+y, x-y alone
  IntervalVector c{Interval(0, 10), Interval(0, 10)};
  ASSERT_TRUE(v.hc4_revise(c, IntervalVector{Interval(0, 1), Interval(0, 1)}));
  EXPECT_EQ(c[0], Interval(0, 1));
  EXPECT_EQ(c[1], Interval(0, 1));
}

TEST(Hc4, DimensionErrors) {
  Function f({"x1", "x2"}, "(x1, x2)");
  IntervalVector x(3);
  EXPECT_THROW(f.hc4_revise(x, IntervalVector(2)), DimensionError);
  IntervalVector y(2);
  EXPECT_THROW(f.hc4_revise(y, IntervalVector(1)), DimensionError);
  EXPECT_THROW(f.hc4_revise(y, Interval(0.0)), DimensionError);
}

// Contraction and consistency on random inputs: a point whose image is
// proven in y is never removed; the result is a subset of the input.
TEST(Hc4, NeverRemovesASolution) {
  const std::vector<std::string> exprs = {
      "sqrt((x1 + 0.5)^2 + (x2 - 4)^2)", "x1 * x2 - x1^3 + 0.1", "sin(x1) * cos(x2) + exp(-x1^2)",
      "atan2(x2, x1) + tanh(x1 * x2)", "abs(x1 - x2) + min(x1, x2) * max(x1, 0.3)",
      "x1 / (1 + x2^2) - log(1 + x1^2)", "cosh(x1) - sinh(x2) + atan(x1 - x2)", "(x1 - x2)^4 + root(x1, 3) - x2^-2",
      "sqrt(abs(x1)) * sign(x2) + asin(tanh(x2))", "pow(1 + x1^2, x2) + acos(0.5 * sin(x1))",
      "x1 * x1 - 2 * x1 * x2 + x2 * x2", "tan(x1 / 3) + [0.1, 0.2] * x2 - pi", "exp(x1) - x2^3 / (x1 - 0.5)",
      "sqr(sin(x1 + x2)) + log(x2)", "cos(x1) * x1 - 1 / x2"};
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> c(-4, 4), w(0, 3), u(0, 1);
  int kept = 0, contracted = 0;
  for (const std::string& e : exprs) {
    Function f({"x1", "x2"}, e);
    for (int k = 0; k < 300; ++k) {
      IntervalVector box(2);
      for (std::size_t i = 0; i < 2; ++i) {
        const double a = c(rng);
        box[i] = Interval(a, a + w(rng));
      }
      // Target: around the image of a random point, so that solutions exist.
      Vector p0{box[0].lb() + u(rng) * box[0].diam(), box[1].lb() + u(rng) * box[1].diam()};
      const Interval fp0 = f.eval(IntervalVector::from_point(p0));
      if (fp0.is_empty() || fp0.is_unbounded()) continue;
      const Interval y(fp0.lb() - w(rng) * 0.5, fp0.ub() + w(rng) * 0.5);
      IntervalVector x = box;
      f.hc4_revise(x, IntervalVector{y});
      ASSERT_TRUE(x.is_subset(box)) << e;
      if (x != box) ++contracted;
      for (int s = 0; s < 40; ++s) {
        const Vector p = s == 0 ? p0 : Vector{box[0].lb() + u(rng) * box[0].diam(), box[1].lb() + u(rng) * box[1].diam()};
        const Interval fp = f.eval(IntervalVector::from_point(p));
        if (!fp.is_empty() && fp.is_subset(y)) {
          ++kept;
          ASSERT_TRUE(x.contains(p)) << e << " removed (" << p[0] << ", " << p[1] << ") from " << box << " to " << x
                                     << " with y = " << y;
        }
      }
    }
  }
  EXPECT_GT(kept, 1000);
  EXPECT_GT(contracted, 500);
}

// The backward pass skips the nodes still at their forward value whose
// operation is defined on all of its operands: bit for bit the same result as
// projecting every node, on random boxes and targets (some outputs left wide
// so that whole sub-DAGs stay idle; operations with restricted domains too).
TEST(Hc4, SkippingIdleNodesChangesNothing) {
  const std::vector<std::string> exprs = {
      "(sqrt((x1 - 3)^2 + (x2 + 1)^2), ((x1 - 3) * x3 + (x2 + 1) * x4) / sqrt((x1 - 3)^2 + (x2 + 1)^2), "
      "sign(x1 - 3) / sqrt(1 + ((x2 + 1) / (x1 - 3))^2) * x3)",
      "(x1 * x2 + sin(x1), x1 * x2 / (x3^2 + 1), log(x4) - exp(x1 - x2))",
      "(abs(x1 - x2) + min(x1, x3) * max(x2, x4), atan(x1 * x4) - tanh(x3), cosh(x2) - sinh(x4))",
      "(x1^-2 + sqrt(x2) - x3^-1, pow(x1, x2) + root(x3, 4), tan(x4) + asin(0.5 * x1) + acos(x2 / 3) + atan2(x2, x3))",
      "(x1 / x2 + x3 / (x4 - 1), sqrt(x1 - x2) * x3, log(x1 * x2) + x4^-3)"};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> c(-4, 4), w(0, 3), u(0, 1);
  int compared = 0, contracted = 0;
  for (const std::string& e : exprs) {
    const Function f({"x1", "x2", "x3", "x4"}, e);
    const detail::Tape t(f.exprs(), f.var_names());
    std::vector<Interval> skip(t.size()), full(t.size());
    for (int k = 0; k < 400; ++k) {
      IntervalVector x(4);
      for (std::size_t i = 0; i < 4; ++i) {
        const double a = c(rng);
        x[i] = Interval(a, a + w(rng));
      }
      // Targets around the image of the box: some outputs tight, some wide.
      const IntervalVector fx = f.eval_vector(x);
      IntervalVector y(3);
      for (std::size_t i = 0; i < 3; ++i) {
        if (fx[i].is_empty() || fx[i].is_unbounded() || u(rng) < 0.3) continue;
        const double m = fx[i].lb() + u(rng) * fx[i].diam();
        y[i] = Interval(m - w(rng) * 0.2, m + w(rng) * 0.2);
      }
      t.forward(x.components().data(), skip.data());
      full = skip;
      const bool ok_skip = t.backward(skip.data(), y.components().data());
      const bool ok_full = t.backward(full.data(), y.components().data(), false);
      ASSERT_EQ(ok_skip, ok_full) << e << " on " << x;
      if (!ok_full) continue;
      ++compared;
      for (std::size_t i = 0; i < t.size(); ++i) ASSERT_EQ(skip[i], full[i]) << e << " slot " << i << " on " << x;
      for (std::size_t i = 0; i < 4; ++i) contracted += full[i] != x[i] ? 1 : 0;
    }
  }
  EXPECT_GT(compared, 800);
  EXPECT_GT(contracted, 400);
}

// hc4_revise_batch equals hc4_revise box by box, across chunks, with empty
// and inconsistent boxes among the others.
TEST(Hc4, BatchEqualsBoxByBox) {
  const Function f({"y", "x1", "x2"}, "(y - sqrt((x1 - 1)^2 + (x2 + 2)^2), x1 / x2 - y)");
  const IntervalVector target{Interval(0.0), Interval(-0.5, 0.5)};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> c(-5, 5), w(0, 4);
  const std::size_t count = 700;
  std::vector<std::vector<Interval>> cols(3, std::vector<Interval>(count));
  std::vector<IntervalVector> boxes;
  for (std::size_t j = 0; j < count; ++j) {
    IntervalVector b(3);
    for (std::size_t i = 0; i < 3; ++i) {
      const double a = c(rng);
      b[i] = j % 97 == 5 && i == 1 ? Interval::empty() : Interval(a, a + w(rng));
      cols[i][j] = b[i];
    }
    boxes.push_back(b);
  }
  const std::vector<Interval*> xs{cols[0].data(), cols[1].data(), cols[2].data()};
  f.hc4_revise_batch(xs, count, target);
  int emptied = 0, contracted = 0;
  for (std::size_t j = 0; j < count; ++j) {
    IntervalVector b = boxes[j];
    const bool ok = f.hc4_revise(b, target);
    emptied += ok ? 0 : 1;
    contracted += ok && b != boxes[j] ? 1 : 0;
    for (std::size_t i = 0; i < 3; ++i) ASSERT_EQ(cols[i][j], b[i]) << "box " << j << " " << boxes[j];
  }
  EXPECT_GT(emptied, 50);
  EXPECT_GT(contracted, 50);
  EXPECT_THROW(f.hc4_revise_batch(std::vector<Interval*>(2), count, target), DimensionError);
  EXPECT_THROW(f.hc4_revise_batch(xs, count, IntervalVector(1)), DimensionError);
}
