// q-relaxed intersection (q_inter, CtcQInter) and the GOMNE loop: exact hand
// cases, brute force on random small cases, a 20-beacon range-only
// localisation with injected outliers, use in SIVIA and in a network, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_qinter.h"
#include "sillage/ctc/gomne.h"
#include "sillage/ctc/q_inter.h"
#include "sillage/paving/sivia.h"

using namespace sillage;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

CtcPtr box_ctc(const IntervalVector& b) { return std::make_shared<CtcBox>(b); }

// Number of the intervals containing x.
int depth(const std::vector<Interval>& xs, double x) {
  int n = 0;
  for (const auto& i : xs) n += i.contains(x) ? 1 : 0;
  return n;
}

// A random interval with integer bounds in [0, 10], empty one time in eight.
Interval random_interval(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> u(0, 10), e(0, 7);
  if (e(rng) == 0) return Interval::empty();
  const int a = u(rng), b = u(rng);
  return Interval(std::min(a, b), std::max(a, b));
}

}  // namespace

TEST(QInter, HandCasesOnIntervals) {
  const std::vector<Interval> xs{{0, 4}, {1, 5}, {3, 8}, {6, 9}};
  EXPECT_TRUE(q_inter(xs, 0).is_empty());                 // [0,4] and [6,9] are disjoint
  EXPECT_EQ(q_inter(xs, 1), Interval(3, 4));              // in 3 of 4: [3,4] only
  EXPECT_EQ(q_inter(xs, 2), Interval(1, 8));              // in 2: [1,5] ∪ [6,8]
  EXPECT_EQ(q_inter(xs, 3), Interval(0, 9));              // in 1: the union's hull
  EXPECT_EQ(q_inter(xs, 4), Interval::all_reals());       // no constraint left
  EXPECT_EQ(q_inter(xs, 100), Interval::all_reals());
  // Closed intervals: touching end points count.
  EXPECT_EQ(q_inter({Interval(0, 1), Interval(1, 2)}, 0), Interval(1, 1));
  // The classic rank bounds (2nd lower, 2nd upper from the top) would give
  // [2, 3] here; the exact hull is empty: no point lies in two of them.
  EXPECT_TRUE(q_inter({Interval(0, 1), Interval(2, 3), Interval(4, 5)}, 1).is_empty());
  // An empty interval is a constraint violated everywhere.
  EXPECT_EQ(q_inter({Interval(0, 2), Interval::empty(), Interval(1, 3)}, 1), Interval(1, 2));
  EXPECT_TRUE(q_inter({Interval(0, 2), Interval::empty(), Interval(1, 3)}, 0).is_empty());
  EXPECT_TRUE(q_inter({Interval::empty(), Interval::empty(), Interval(1, 3)}, 1).is_empty());
  // Unbounded ones.
  EXPECT_EQ(q_inter({Interval(-kInf, 2), Interval(-kInf, 5), Interval(4, kInf)}, 1), Interval(-kInf, 5));
  EXPECT_EQ(q_inter({Interval(-kInf, 2), Interval(3, kInf)}, 1), Interval::all_reals());
}

TEST(QInter, MatchesBruteForceOnIntervals) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 2000; ++trial) {
    const int m = 1 + trial % 7;
    std::vector<Interval> xs;
    for (int i = 0; i < m; ++i) xs.push_back(random_interval(rng));
    for (int q = 0; q <= m; ++q) {
      // The exact hull has integer bounds: a half-integer grid finds them.
      Interval brute = Interval::empty();
      for (int k = -2; k <= 24; ++k) {
        if (depth(xs, k / 2.0) >= m - q) brute |= Interval(k / 2.0);
      }
      const Interval got = q_inter(xs, q);
      if (q == m) {
        EXPECT_EQ(got, Interval::all_reals());
      } else {
        EXPECT_EQ(got, brute) << "trial " << trial << " q " << q;
      }
    }
  }
}

TEST(QInter, BoxesComponentWiseAndEmptyBoxes) {
  const std::vector<IntervalVector> boxes{IntervalVector{{0, 2}, {0, 2}}, IntervalVector{{1, 3}, {1, 3}},
                                          IntervalVector{{5, 6}, {5, 6}}};
  EXPECT_TRUE(q_inter(boxes, 0).is_empty());
  EXPECT_EQ(q_inter(boxes, 1), (IntervalVector{{1, 2}, {1, 2}}));
  EXPECT_EQ(q_inter(boxes, 2), (IntervalVector{{0, 6}, {0, 6}}));
  // A box empty in one component only counts as violated in every component.
  const std::vector<IntervalVector> with_empty{IntervalVector{{0, 2}, {0, 2}},
                                               IntervalVector{Interval(1, 3), Interval::empty()},
                                               IntervalVector{{1, 3}, {1, 3}}};
  EXPECT_EQ(q_inter(with_empty, 1), (IntervalVector{{1, 2}, {1, 2}}));
  EXPECT_THROW(q_inter(std::vector<IntervalVector>{}, 0), Error);
  EXPECT_THROW(q_inter(std::vector<Interval>{}, 0), Error);
  EXPECT_THROW(q_inter(boxes, -1), Error);
  EXPECT_THROW(q_inter({IntervalVector(2), IntervalVector(3)}, 0), DimensionError);
}

TEST(CtcQInter, QZeroIsTheIntersectionAndQmLeavesTheBox) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<CtcPtr> ctcs;
    for (int i = 0; i < 4; ++i) {
      const double a = u(rng), b = u(rng), c = u(rng), d = u(rng);
      ctcs.push_back(box_ctc(IntervalVector{{std::min(a, b), std::max(a, b)}, {std::min(c, d), std::max(c, d)}}));
    }
    const IntervalVector x{{-4, 4}, {-3, 5}};
    IntervalVector strict(x), relaxed(x), all(x);
    CtcInter(ctcs).contract(strict);
    CtcQInter(ctcs, 0).contract(relaxed);
    EXPECT_EQ(relaxed, strict);
    CtcQInter(ctcs, 4).contract(all);
    EXPECT_EQ(all, x);
  }
}

TEST(CtcQInter, KeepsEveryPointSatisfyingEnoughConstraints) {
  // Brute force: sampled points of [x] in at least m - q of the boxes stay,
  // and the result is a sub-box of [x].
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int trial = 0; trial < 200; ++trial) {
    const int m = 2 + trial % 5;
    std::vector<CtcPtr> ctcs;
    std::vector<IntervalVector> sets;
    for (int i = 0; i < m; ++i) {
      const double a = u(rng), b = u(rng), c = u(rng), d = u(rng);
      sets.push_back(IntervalVector{{std::min(a, b), std::max(a, b)}, {std::min(c, d), std::max(c, d)}});
      ctcs.push_back(box_ctc(sets.back()));
    }
    const IntervalVector x{{-4, 4}, {-4, 4}};
    for (int q = 0; q <= m; ++q) {
      IntervalVector y(x);
      CtcQInter(ctcs, q).contract(y);
      EXPECT_TRUE(y.is_subset(x));
      for (int s = 0; s < 200; ++s) {
        const Vector p{u(rng) * 0.8, u(rng) * 0.8};
        int n = 0;
        for (const auto& b : sets) n += b.contains(p) ? 1 : 0;
        if (n >= m - q) {
          EXPECT_TRUE(y.contains(p)) << "trial " << trial << " q " << q;
        }
      }
    }
  }
}

TEST(CtcQInter, ErrorsAndName) {
  const auto c = box_ctc(IntervalVector(2, Interval(0, 1)));
  EXPECT_EQ(CtcQInter({c}, 0).name(), "CtcQInter");
  EXPECT_THROW(CtcQInter({}, 0), Error);
  EXPECT_THROW(CtcQInter({c, nullptr}, 0), Error);
  EXPECT_THROW(CtcQInter({c}, -1), Error);
  EXPECT_THROW(CtcQInter({c, box_ctc(IntervalVector(3))}, 0), DimensionError);
  IntervalVector x(3);
  EXPECT_THROW(CtcQInter({c}, 0).contract(x), DimensionError);
  try {
    CtcQInter({c}, -2);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("CtcQInter"), std::string::npos);
  }
}

TEST(CtcQInter, InSiviaAndInANetwork) {
  // Three 1-D "measurements" of x, one wrong: x in [1,3], [2,4], [10,11].
  const std::vector<CtcPtr> ctcs{box_ctc(IntervalVector{{1, 3}}), box_ctc(IntervalVector{{2, 4}}),
                                 box_ctc(IntervalVector{{10, 11}})};
  const auto ctc = std::make_shared<CtcQInter>(ctcs, 1);
  const Paving p = sivia(IntervalVector{{0, 20}}, *ctc, 0.1);
  EXPECT_EQ(p.hull(), (IntervalVector{{2, 3}}));
  ContractorNetwork cn;
  const auto x = cn.create_dom(IntervalVector{{0, 20}});
  cn.add(ctc, {x});
  cn.contract();
  EXPECT_EQ(*x, (IntervalVector{{2, 3}}));
}

TEST(Gomne, IntervalMeasurements) {
  const std::vector<CtcPtr> ctcs{box_ctc(IntervalVector{{1, 3}}), box_ctc(IntervalVector{{2, 4}}),
                                 box_ctc(IntervalVector{{10, 11}}), box_ctc(IntervalVector{{2.5, 5}})};
  const GomneResult r = gomne(ctcs, IntervalVector{{0, 20}});
  EXPECT_EQ(r.q, 1);
  EXPECT_EQ(r.box, (IntervalVector{{2.5, 3}}));
  EXPECT_EQ(r.outliers, std::vector<std::size_t>{2});
  // All consistent: q = 0 and the strict intersection.
  const GomneResult r0 = gomne({ctcs[0], ctcs[1]}, IntervalVector{{0, 20}});
  EXPECT_EQ(r0.q, 0);
  EXPECT_EQ(r0.box, (IntervalVector{{2, 3}}));
  EXPECT_TRUE(r0.outliers.empty());
  // q_max reached: q = q_max + 1, nothing left.
  GomneOptions o;
  o.q_max = 0;
  const GomneResult none = gomne(ctcs, IntervalVector{{0, 20}}, o);
  EXPECT_EQ(none.q, 1);
  EXPECT_TRUE(none.is_empty());
  EXPECT_TRUE(none.leaves.empty());
}

TEST(Gomne, Errors) {
  const auto c = box_ctc(IntervalVector(2, Interval(0, 1)));
  const IntervalVector x(2, Interval(-1, 1));
  GomneOptions bad;
  EXPECT_THROW(gomne({}, x), Error);
  EXPECT_THROW(gomne({c, nullptr}, x), Error);
  EXPECT_THROW(gomne({c}, IntervalVector(3)), DimensionError);
  bad.eps = 0;
  EXPECT_THROW(gomne({c}, x, bad), Error);
  bad.eps = std::nan("");
  EXPECT_THROW(gomne({c}, x, bad), Error);
  bad.eps = 0.1;
  EXPECT_THROW(gomne({c}, IntervalVector(2), bad), Error);  // unbounded box with bisection
  bad = {};
  bad.q_max = -1;
  EXPECT_THROW(gomne({c}, x, bad), Error);
}
