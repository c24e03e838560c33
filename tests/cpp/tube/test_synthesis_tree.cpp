// SynthesisTree: every query equals, bit for bit, a linear scan over the same
// slices; hull queries equal Tube::operator()([t]).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "sillage/error.h"
#include "sillage/tube/synthesis_tree.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube.h"

namespace sillage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Data {
  std::vector<double> times;
  std::vector<Interval> slices, gates;
};

// Random non-uniform grid, random slices, some unbounded (when `unbounded`).
Data random_data(std::mt19937_64& rng, std::size_t n, bool unbounded, bool uniform) {
  std::uniform_real_distribution<double> u(-3.0, 3.0), w(0.01, 1.0), p(0.0, 1.0);
  Data d;
  d.times.resize(n + 1);
  d.times[0] = u(rng);
  for (std::size_t k = 1; k <= n; ++k) d.times[k] = uniform ? d.times[0] + 0.1 * static_cast<double>(k)
                                                            : d.times[k - 1] + w(rng);
  for (std::size_t k = 0; k < n; ++k) {
    double a = u(rng), b = u(rng);
    if (a > b) std::swap(a, b);
    if (unbounded && p(rng) < 0.08) a = -kInf;
    if (unbounded && p(rng) < 0.08) b = kInf;
    d.slices.emplace_back(a, b);
  }
  for (std::size_t k = 0; k <= n; ++k) {
    const double c = u(rng);
    d.gates.emplace_back(c, c + w(rng));
  }
  return d;
}

// ---- the reference: a linear scan with the same arithmetic ----
struct Ref {
  std::vector<PrimitiveValue> lower, upper;
  const Data* d;

  explicit Ref(const Data& data) : d(&data) {
    const std::size_t n = data.slices.size();
    lower.resize(n + 1);
    upper.resize(n + 1);
    for (std::size_t k = 0; k < n; ++k) {
      const Interval width = Interval(data.times[k + 1]) - Interval(data.times[k]);
      const Interval& s = data.slices[k];
      lower[k + 1] = lower[k];
      upper[k + 1] = upper[k];
      if (s.lb() == -kInf) ++lower[k + 1].rank.passed; else lower[k + 1].fin = lower[k].fin + width * Interval(s.lb());
      if (s.ub() == kInf) ++upper[k + 1].rank.passed; else upper[k + 1].fin = upper[k].fin + width * Interval(s.ub());
    }
  }

  PrimitiveValue at(bool up, double t) const {
    const auto& v = up ? upper : lower;
    const auto& ts = d->times;
    for (std::size_t k = 0; k < d->slices.size(); ++k) {
      if (t == ts[k]) return v[k];
      if (t == ts[k + 1]) return v[k + 1];
      if (ts[k] < t && t < ts[k + 1]) {
        const double b = up ? d->slices[k].ub() : d->slices[k].lb();
        if (std::isinf(b)) return {{v[k].rank.passed, t}, v[k].fin};
        return {v[k].rank, v[k].fin + (Interval(t) - Interval(ts[k])) * Interval(b)};
      }
    }
    ADD_FAILURE() << "t outside";
    return {};
  }

  PrimitiveRange range(bool up, double a, double b) const {
    const auto& v = up ? upper : lower;
    std::vector<PrimitiveValue> cand{at(up, a), at(up, b)};
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (a < d->times[k] && d->times[k] < b) cand.push_back(v[k]);
    }
    PrimitiveRange r;
    r.rank_first = cand[0].rank;
    r.rank_last = cand[1].rank;
    auto over = [&](const Rank& c, Interval& mn, Interval& mx) {
      double a1 = kInf, a2 = kInf, b1 = -kInf, b2 = -kInf;
      for (const auto& x : cand) {
        if (x.rank != c) continue;
        a1 = std::min(a1, x.fin.lb());
        a2 = std::min(a2, x.fin.ub());
        b1 = std::max(b1, x.fin.lb());
        b2 = std::max(b2, x.fin.ub());
      }
      mn = Interval(a1, a2);
      mx = Interval(b1, b2);
    };
    over(r.rank_first, r.min_first, r.max_first);
    over(r.rank_last, r.min_last, r.max_last);
    return r;
  }
};

void expect_same(const Interval& x, const Interval& y, const char* what) {
  EXPECT_EQ(x.lb(), y.lb()) << what;
  EXPECT_EQ(x.ub(), y.ub()) << what;
}

void expect_same(const PrimitiveRange& x, const PrimitiveRange& y) {
  EXPECT_TRUE(x.rank_first == y.rank_first);
  EXPECT_TRUE(x.rank_last == y.rank_last);
  expect_same(x.min_first, y.min_first, "min_first");
  expect_same(x.max_first, y.max_first, "max_first");
  expect_same(x.min_last, y.min_last, "min_last");
  expect_same(x.max_last, y.max_last, "max_last");
}

// A random sub-interval of [t0, tf], sometimes with ends on time points.
Interval random_t(std::mt19937_64& rng, const Data& d) {
  std::uniform_real_distribution<double> u(d.times.front(), d.times.back());
  std::uniform_int_distribution<std::size_t> k(0, d.times.size() - 1);
  std::uniform_int_distribution<int> kind(0, 5);
  double a = kind(rng) == 0 ? d.times[k(rng)] : u(rng);
  double b = kind(rng) == 0 ? d.times[k(rng)] : u(rng);
  if (kind(rng) == 1) b = a;
  if (a > b) std::swap(a, b);
  return {a, b};
}

TEST(SynthesisTree, PrimitiveRangesEqualLinearScan) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial % 37) * 3;
    const Data d = random_data(rng, n, trial % 2 == 1, trial % 3 == 0);
    const SynthesisTree tree(d.times, d.slices, d.gates);
    const Ref ref(d);
    for (std::size_t k = 0; k <= n; ++k) {
      EXPECT_TRUE(tree.lower_prefix(k).rank == ref.lower[k].rank);
      expect_same(tree.lower_prefix(k).fin, ref.lower[k].fin, "lower prefix");
      expect_same(tree.upper_prefix(k).fin, ref.upper[k].fin, "upper prefix");
    }
    for (int q = 0; q < 40; ++q) {
      const Interval t = random_t(rng, d);
      PrimitiveRange l, u;
      tree.ranges(t, l, u);
      expect_same(l, ref.range(false, t.lb(), t.ub()));
      expect_same(u, ref.range(true, t.lb(), t.ub()));
      expect_same(tree.lower_range(t).min_first, l.min_first, "lower_range");
      expect_same(tree.upper_range(t).max_last, u.max_last, "upper_range");
    }
  }
}

TEST(SynthesisTree, HullsEqualLinearScanAndTubeEvaluation) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial) * 5;
    const Data d = random_data(rng, n, true, trial % 2 == 0);
    const SynthesisTree tree(d.times, d.slices, d.gates);
    std::uniform_int_distribution<std::size_t> k(0, n - 1);
    for (int q = 0; q < 30; ++q) {
      std::size_t i = k(rng), j = k(rng);
      if (i > j) std::swap(i, j);
      Interval h = Interval::empty();
      for (std::size_t m = i; m <= j; ++m) h |= d.slices[m];
      expect_same(tree.slice_hull(i, j), h, "slice hull");
    }
    const auto td = TDomain::create(d.times);
    const Tube x(td, d.slices, d.gates);
    for (int q = 0; q < 30; ++q) {
      const Interval t = random_t(rng, d);
      expect_same(tree.eval(t), x(t), "eval vs Tube");
      EXPECT_EQ(tree.slice_index(t.lb()), td->slice_index(t.lb()));
    }
    EXPECT_TRUE(tree.eval(Interval::empty()).is_empty());
  }
}

TEST(SynthesisTree, SmallHandComputedPrefixes) {
  // Slices [1,2], [-1,3], [0,0.5], [2,4] on [0,4]: L = 0,1,0,0,2 and U = 0,2,5,5.5,9.5.
  const std::vector<double> ts{0, 1, 2, 3, 4};
  const std::vector<Interval> s{{1, 2}, {-1, 3}, {0, 0.5}, {2, 4}};
  const SynthesisTree tree(ts, s);
  const double l[] = {0, 1, 0, 0, 2}, u[] = {0, 2, 5, 5.5, 9.5};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(tree.lower_prefix(k).fin, Interval(l[k]));
    EXPECT_EQ(tree.upper_prefix(k).fin, Interval(u[k]));
  }
  EXPECT_EQ(tree.lower_at(1.5).fin, Interval(0.5));
  EXPECT_EQ(tree.upper_at(1.5).fin, Interval(3.5));
  const PrimitiveRange r = tree.lower_range(Interval(0.5, 3.5));
  EXPECT_EQ(r.min_first, Interval(0.0));
  EXPECT_EQ(r.max_first, Interval(1.0));
  EXPECT_EQ(tree.slice_hull(0, 3), Interval(-1, 4));
  EXPECT_EQ(tree.eval(Interval(2.5, 3.5)), Interval(0, 4));
  EXPECT_FALSE(tree.has_empty_slice());
}

TEST(SynthesisTree, UnboundedAndEmptySlices) {
  const std::vector<double> ts{0, 1, 2, 3};
  const SynthesisTree tree(ts, std::vector<Interval>{{1, 1}, {-kInf, 1}, {1, kInf}});
  EXPECT_EQ(tree.lower_prefix(3).rank.passed, 1u);
  EXPECT_EQ(tree.lower_prefix(3).fin, Interval(2.0));  // the finite part only
  EXPECT_EQ(tree.upper_at(2.5).rank.passed, 0u);
  EXPECT_EQ(tree.upper_at(2.5).rank.inside, 2.5);
  EXPECT_EQ(tree.upper_prefix(3).fin, Interval(2.0));
  const SynthesisTree e(ts, std::vector<Interval>{{1, 1}, Interval::empty(), {1, 2}});
  EXPECT_TRUE(e.has_empty_slice());
  EXPECT_EQ(e.slice_hull(0, 2), Interval(1, 2));
}

TEST(SynthesisTree, InvalidInput) {
  const std::vector<double> ts{0, 1, 2};
  const std::vector<Interval> s{{0, 1}, {0, 1}};
  EXPECT_THROW(SynthesisTree(ts, std::vector<Interval>{{0, 1}}), DimensionError);
  EXPECT_THROW(SynthesisTree(ts, s, std::vector<Interval>{{0, 1}}), DimensionError);
  EXPECT_THROW(SynthesisTree(std::vector<double>{0, 2, 1}, s), Error);
  EXPECT_THROW(SynthesisTree(std::vector<double>{0, 1, kInf}, s), Error);
  const SynthesisTree tree(ts, s);
  EXPECT_THROW(tree.slice_index(2.5), Error);
  EXPECT_THROW(tree.slice_index(std::nan("")), Error);
  EXPECT_THROW(tree.eval(Interval(-1, 1)), Error);
  EXPECT_THROW(tree.lower_range(Interval(1, 3)), Error);
  EXPECT_THROW(tree.slice_hull(0, 2), Error);
  EXPECT_EQ(tree.slice_index(2.0), 1u);
  EXPECT_EQ(tree.slice_index(1.0), 1u);
}

}  // namespace
}  // namespace sillage
