// GOMNE on a synthetic range-only localisation: 20 beacons, k wrong ranges
// injected at known indices. The truth stays in the box, q = k is found and
// the wrong ranges are named; with no outlier, q = 0 and the box is the
// strict intersection.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_qinter.h"
#include "sillage/ctc/gomne.h"

using namespace sillage;

namespace {

struct Ranges {
  Vector truth{3.25, -1.5};
  std::vector<CtcPtr> ctcs;
};

// Beacons at integer positions in [-40, 40]^2; each range is the true
// distance plus a noise in [-0.05, 0.05], measured as +-0.1 around it; the
// ranges at `wrong` are shifted by 5 to 15 (a detectable outlier).
Ranges make_ranges(const std::vector<std::size_t>& wrong, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> pos(-40, 40);
  std::uniform_real_distribution<double> noise(-0.05, 0.05), shift(5, 15);
  Ranges r;
  for (std::size_t i = 0; i < 20; ++i) {
    const int bx = pos(rng), by = pos(rng);
    double d = std::hypot(r.truth[0] - bx, r.truth[1] - by) + noise(rng);
    if (std::find(wrong.begin(), wrong.end(), i) != wrong.end()) d += (i % 2 ? -1 : 1) * shift(rng);
    const Function f({"x1", "x2"}, "sqrt((x1 - (" + std::to_string(bx) + "))^2 + (x2 - (" + std::to_string(by) + "))^2)");
    r.ctcs.push_back(std::make_shared<CtcFunction>(f, Interval(std::max(0.0, d - 0.1), d + 0.1)));
  }
  return r;
}

const IntervalVector kX0{{-50, 50}, {-50, 50}};

}  // namespace

TEST(GomneRanges, FindsTheInjectedOutliers) {
  const std::vector<std::vector<std::size_t>> cases{{}, {7}, {2, 13}, {0, 9, 17}};
  for (const auto& wrong : cases) {
    const Ranges r = make_ranges(wrong, 42);
    GomneOptions o;
    o.eps = 0.5;
    const GomneResult g = gomne(r.ctcs, kX0, o);
    EXPECT_EQ(g.q, static_cast<int>(wrong.size()));
    EXPECT_TRUE(g.box.contains(r.truth)) << g.box;
    EXPECT_TRUE(g.box.is_subset(kX0));
    EXPECT_EQ(g.outliers, wrong);
    EXPECT_LT(g.box.max_diam(), 1.0) << g.box;
    bool in_a_leaf = false;
    for (const auto& leaf : g.leaves) in_a_leaf = in_a_leaf || leaf.contains(r.truth);
    EXPECT_TRUE(in_a_leaf);
  }
}

TEST(GomneRanges, NoOutlierGivesTheStrictIntersection) {
  const Ranges r = make_ranges({}, 7);
  const GomneResult g = gomne(r.ctcs, kX0);  // contraction only
  IntervalVector strict(kX0);
  CtcFixPoint(std::make_shared<CtcInter>(r.ctcs), 0.01).contract(strict);
  EXPECT_EQ(g.q, 0);
  EXPECT_EQ(g.box, strict);
  EXPECT_TRUE(g.box.contains(r.truth));
}

TEST(GomneRanges, TruthKeptByEveryRelaxation) {
  // With k wrong ranges, every q >= k keeps the truth, contraction or paving.
  const Ranges r = make_ranges({4, 11}, 9);
  for (int q = 2; q <= 5; ++q) {
    IntervalVector x(kX0);
    CtcFixPoint(std::make_shared<CtcQInter>(r.ctcs, q), 0.0).contract(x);
    EXPECT_TRUE(x.contains(r.truth)) << "q " << q;
    EXPECT_TRUE(x.is_subset(kX0));
  }
}
