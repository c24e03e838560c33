// SynthesisTree: every query equals, bit for bit, a linear scan over the same
// slices; hull queries equal Tube::operator()([t]).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "sillage/error.h"
#include "sillage/tube/prefix_lanes.h"
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
    // The least lower end and the greatest upper end over the times of rank c.
    auto over = [&](const Rank& c, double& mn, double& mx) {
      mn = kInf;
      mx = -kInf;
      for (const auto& x : cand) {
        if (x.rank != c) continue;
        mn = std::min(mn, x.fin.lb());
        mx = std::max(mx, x.fin.ub());
      }
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
  EXPECT_EQ(x.min_first, y.min_first) << "min_first";
  EXPECT_EQ(x.max_first, y.max_first) << "max_first";
  EXPECT_EQ(x.min_last, y.min_last) << "min_last";
  EXPECT_EQ(x.max_last, y.max_last) << "max_last";
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

// The tree's prefixes (every `step`-th time point) and `queries` random
// range queries equal the linear-scan reference bit for bit.
void expect_tree_equals_scan(std::mt19937_64& rng, const Data& d, const SynthesisTree& tree, const Ref& ref,
                             std::size_t step, int queries) {
  for (std::size_t k = 0; k < d.times.size(); k += step) {
    EXPECT_TRUE(tree.lower_prefix(k).rank == ref.lower[k].rank);
    EXPECT_TRUE(tree.upper_prefix(k).rank == ref.upper[k].rank);
    expect_same(tree.lower_prefix(k).fin, ref.lower[k].fin, "lower prefix");
    expect_same(tree.upper_prefix(k).fin, ref.upper[k].fin, "upper prefix");
  }
  for (int q = 0; q < queries; ++q) {
    const Interval t = random_t(rng, d);
    PrimitiveRange l, u;
    tree.ranges(t, l, u);
    expect_same(l, ref.range(false, t.lb(), t.ub()));
    expect_same(u, ref.range(true, t.lb(), t.ub()));
    EXPECT_EQ(tree.lower_range(t).min_first, l.min_first);
    EXPECT_EQ(tree.upper_range(t).max_last, u.max_last);
  }
}

TEST(SynthesisTree, PrimitiveRangesEqualLinearScan) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial % 37) * 3;
    const Data d = random_data(rng, n, trial % 2 == 1, trial % 3 == 0);
    const SynthesisTree tree(d.times, d.slices, d.gates);
    expect_tree_equals_scan(rng, d, tree, Ref(d), 1, 40);
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
    Tube x(td, d.slices);  // the random gates may miss their slices: set_gate takes them
    for (std::size_t k = 0; k < d.gates.size(); ++k) x.set_gate(k, d.gates[k]);
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
  EXPECT_EQ(r.min_first, 0.0);
  EXPECT_EQ(r.max_first, 1.0);
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

TEST(SynthesisTree, LargeTreesEqualLinearScan) {
  // Several levels of blocks, anchors and tree nodes; sparse unbounded slices.
  std::mt19937_64 rng(99);
  for (const std::size_t n : {257u, 1000u, 4099u}) {
    for (const bool unbounded : {false, true}) {
      Data d = random_data(rng, n, false, n == 1000);
      if (n == 257) {  // extreme values: the prefix steps fall back to the Interval operators
        for (std::size_t k = 0; k < n; k += 5) {
          d.slices[k] = k % 3 == 0 ? Interval(1e307, 1.5e308) : Interval(-1e-310, 1e-300 * static_cast<double>(k));
        }
      }
      if (unbounded) {
        d.slices[n / 3] = Interval(-kInf, 1.0);
        d.slices[n / 3 + 9] = Interval(-kInf, kInf);
        d.slices[2 * n / 3] = Interval(0.5, kInf);
      }
      const SynthesisTree tree(d.times, d.slices, d.gates);
      expect_tree_equals_scan(rng, d, tree, Ref(d), 7, 60);
    }
  }
}

// A double with a random sign, mantissa and exponent in [e_lo, e_hi] (or a special value).
double wild(std::mt19937_64& rng, int e_lo, int e_hi) {
  std::uniform_int_distribution<int> kind(0, 19), e(e_lo, e_hi);
  std::uniform_real_distribution<double> m(1.0, 2.0);
  switch (kind(rng)) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return std::numeric_limits<double>::denorm_min() * static_cast<double>(1 + rng() % 1000);
    case 3: return std::numeric_limits<double>::max();
    case 4: return 1.0;
    default: break;
  }
  const double x = std::ldexp(m(rng), e(rng));
  return rng() % 2 ? x : -x;
}

// The prefix step of the tree (fast path and fallback) gives the bits of the
// Interval operators, also on tiny, huge, zero, unbounded and empty operands.
TEST(SynthesisTree, PrefixStepIsTheIntervalArithmetic) {
  std::mt19937_64 rng(5);
  const int ranges[][2] = {{-40, 40}, {-1074, 1023}, {-1000, -900}, {900, 1023}, {-3, 3}};
  std::size_t n_fast = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const auto& r = ranges[trial % 5];
    double t0 = wild(rng, r[0], r[1]), t1 = wild(rng, r[0], r[1]);
    if (trial % 3 == 0) t1 = std::nextafter(t0, kInf);  // the narrowest slice
    if (t0 == t1 || !std::isfinite(t1)) continue;
    if (t0 > t1) std::swap(t0, t1);
    if (!std::isfinite(t1 - t0) && trial % 2 == 0) continue;
    double lo = wild(rng, r[0], r[1]), hi = wild(rng, r[0], r[1]);
    if (lo > hi) std::swap(lo, hi);
    Interval s(lo, hi);
    if (trial % 50 == 1) s = Interval(-kInf, hi);
    if (trial % 50 == 2) s = Interval(lo, kInf);
    if (trial % 50 == 3) s = Interval::empty();
    double l0 = wild(rng, r[0], r[1]), l1 = wild(rng, r[0], r[1]), u0 = wild(rng, r[0], r[1]),
           u1 = wild(rng, r[0], r[1]);
    if (l0 > l1) std::swap(l0, l1);
    if (u0 > u1) std::swap(u0, u1);
    if (trial % 7 == 0) l0 = l1 = u0 = u1 = 0.0;  // the start of the sums
    if (trial % 97 == 0) l0 = -kInf;            // after an overflow
    const Interval l = Interval::from_bounds_unchecked(l0, l1 == -0.0 ? 0.0 : l1);
    const Interval u = Interval::from_bounds_unchecked(u0, u1 == -0.0 ? 0.0 : u1);
    // Reference.
    Interval l_ref = l, u_ref = u;
    if (!s.is_empty()) {
      const Interval width = Interval(t1) - Interval(t0);
      if (s.lb() != -kInf) l_ref = l + width * Interval::from_bounds_unchecked(s.lb(), s.lb());
      if (s.ub() != kInf) u_ref = u + width * Interval::from_bounds_unchecked(s.ub(), s.ub());
    }
    detail::Lanes p = detail::lanes_of(l, u);
    detail::Lanes probe = p;
    if (std::isfinite(s.lb()) && std::isfinite(s.ub())) {
      detail::LaneMask bad{};
      detail::advance_fast(probe, t0, t1, s.lb(), s.ub(), bad);
      n_fast += !detail::any(bad);
    }
    detail::advance(p, t0, t1, s);
    const Interval l_got = detail::lower_of(p), u_got = detail::upper_of(p);
    auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    ASSERT_EQ(bits(l_got.lb()), bits(l_ref.lb())) << t0 << " " << t1 << " " << s << " " << l;
    ASSERT_EQ(bits(l_got.ub()), bits(l_ref.ub())) << t0 << " " << t1 << " " << s << " " << l;
    ASSERT_EQ(bits(u_got.lb()), bits(u_ref.lb())) << t0 << " " << t1 << " " << s << " " << u;
    ASSERT_EQ(bits(u_got.ub()), bits(u_ref.ub())) << t0 << " " << t1 << " " << s << " " << u;
  }
  EXPECT_GT(n_fast, 30000u);  // the fast path was exercised, not only the fallback
}

// A tube's tree reads the tube's storage: once that changes or goes, the tree
// refuses to answer rather than answer from data it was not built from.
TEST(SynthesisTree, TreeOfATubeChecksTheTube) {
  auto td = TDomain::create(0.0, 10.0, 0.01);
  auto x = std::make_unique<Tube>(td, "sin(t) + [-0.1, 0.1]");
  const auto tree = x->synthesis_tree();
  const Interval t(0.5, 9.5);
  EXPECT_EQ(tree->eval(t), (*x)(t));
  EXPECT_NO_THROW(tree->lower_range(t));
  x->set(Interval(5, 6), 500);
  EXPECT_THROW(tree->eval(t), Error);
  EXPECT_THROW(tree->lower_range(t), Error);
  EXPECT_THROW(tree->lower_at(1.0), Error);
  EXPECT_EQ(tree->nb_slices(), 1000u);  // the tree as built
  const auto fresh = x->synthesis_tree();
  EXPECT_EQ(fresh->eval(t).ub(), 6.0);
  td->sample(5.005);  // splits a slice of x: a modification
  EXPECT_THROW(fresh->eval(t), Error);
  const auto third = x->synthesis_tree();
  EXPECT_EQ(third->nb_slices(), 1001u);
  EXPECT_EQ(third->eval(t), (*x)(t));
  x.reset();  // the tube is gone
  EXPECT_THROW(third->eval(t), Error);
  EXPECT_THROW(third->upper_prefix(3), Error);
}

// The bound: a scalar tube with its tree built holds at most 64 bytes
// per slice (32 for slices and gates, the rest for the tree).
TEST(SynthesisTree, TubeWithTreeHoldsAtMost64BytesPerSlice) {
  const std::size_t n = 100000;
  auto td = TDomain::create(0.0, static_cast<double>(n) * 0.01, 0.01);
  ASSERT_EQ(td->nb_slices(), n);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> c(-1, 1), w(0, 0.5), p(0, 1);
  for (const bool unbounded : {false, true}) {
    std::vector<Interval> s(n);
    for (auto& y : s) {
      const double m = c(rng);
      y = Interval(unbounded && p(rng) < 0.1 ? -kInf : m, unbounded && p(rng) < 0.1 ? kInf : m + w(rng));
    }
    const Tube x(td, s);
    const std::size_t bare = x.memory_bytes();
    EXPECT_LE(bare, 33 * n);
    (void)x(Interval(1.0, 900.0));  // a long query builds the tree
    const std::size_t with_tree = x.memory_bytes();
    EXPECT_GT(with_tree, bare);
    EXPECT_LE(with_tree, 64 * n) << static_cast<double>(with_tree) / static_cast<double>(n) << " bytes per slice";
    EXPECT_LE(x.synthesis_tree()->memory_bytes(), 24 * n);
  }
}

}  // namespace
}  // namespace sillage
