// The network's bookkeeping of what woke a node: DirtyAtoms (one bit per node
// and watched atom, read back as sorted positions) and the per-atom index of
// Watchers, each against a brute-force reference on random cases, and a
// network whose node records the dirty positions it is given.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/cn/dirty_atoms.h"
#include "sillage/cn/watchers.h"

using namespace sillage;

namespace {

// A node on given ranges, watching given sub-ranges, that does nothing.
class Idle : public CnNode {
 public:
  Idle(std::vector<AtomRange> ranges, const std::vector<AtomRange>& watch) : CnNode(std::move(ranges)) {
    for (std::size_t g = 0; g < watch.size(); ++g) watch_only(g, watch[g].first, watch[g].count);
  }
  std::string name() const override { return "Idle"; }
  bool run(NodeRun&) const override { return true; }
};

}  // namespace

TEST(DirtyAtoms, PositionsSortedOncePerAtomAgainstASet) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    detail::DirtyAtoms dirty;
    std::vector<Idle> nodes;
    std::vector<std::vector<std::size_t>> bits;  // per node, per range
    const int nb_nodes = 1 + static_cast<int>(rng() % 4);
    for (int i = 0; i < nb_nodes; ++i) {
      std::vector<AtomRange> ranges, watch;
      const std::size_t nb_ranges = 1 + rng() % 3;
      for (std::size_t g = 0; g < nb_ranges; ++g) {
        const std::size_t count = 1 + rng() % 150, first = rng() % (count + 1), n = rng() % (count - first + 1);
        ranges.push_back({g, 0, count});
        watch.push_back({g, first, first + n <= count ? n : 0});
      }
      nodes.emplace_back(ranges, watch);
      bits.emplace_back();
      dirty.add_node(nodes.back(), bits.back());
    }
    dirty.reset();
    // Wake random watched atoms, some many times; the reference is a set of positions.
    std::vector<std::set<std::size_t>> expected(nodes.size());
    std::vector<std::size_t> wakes(nodes.size(), 0);
    for (int k = 0; k < 400; ++k) {
      const std::size_t i = rng() % nodes.size(), g = rng() % nodes[i].ranges().size();
      const AtomRange& w = nodes[i].watched()[g];
      if (w.count == 0) continue;
      const std::size_t a = rng() % w.count;
      const bool first = expected[i].insert(nodes[i].offset(g) + w.first + a).second;
      EXPECT_EQ(dirty.mark(i, bits[i][g] + a), first);
      ++wakes[i];
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      EXPECT_EQ(dirty.wakes(i), wakes[i]);
      std::vector<std::size_t> got;
      dirty.take(i, got);
      EXPECT_EQ(got, std::vector<std::size_t>(expected[i].begin(), expected[i].end()));
      EXPECT_EQ(dirty.wakes(i), 0u);
      dirty.take(i, got);
      EXPECT_TRUE(got.empty());
    }
  }
}

TEST(DirtyAtoms, ResetForgetsEverything) {
  detail::DirtyAtoms dirty;
  Idle node({{0, 0, 10}}, {{0, 0, 10}});
  std::vector<std::size_t> bits, got;
  dirty.add_node(node, bits);
  dirty.reset();
  EXPECT_TRUE(dirty.mark(0, bits[0] + 3));
  dirty.reset();
  EXPECT_EQ(dirty.wakes(0), 0u);
  dirty.take(0, got);
  EXPECT_TRUE(got.empty());
  dirty.clear_nodes();
  EXPECT_EQ(dirty.nb_nodes(), 0u);
}

TEST(Watchers, IndexMatchesEveryWatchCoveringTheAtom) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    const std::size_t n = 1 + rng() % 200;
    detail::Watchers ws(n);
    std::vector<detail::Watchers::Watch> all;
    for (int k = 0; k < 25; ++k) {
      const bool whole = rng() % 4 == 0;
      const std::size_t first = whole ? 0 : rng() % n, count = whole ? n : 1 + rng() % (n - first);
      const detail::Watchers::Watch w{static_cast<std::size_t>(k), first, count, rng() % 1000, rng() % 1000};
      all.push_back(w);
      ws.add(w);
      if (rng() % 5 == 0) ws.index();  // an index built early is rebuilt after more adds
    }
    ws.index();
    for (std::size_t a = 0; a < n; ++a) {
      // Whole-domain watches first, then the others, each in the order of add().
      std::vector<std::tuple<std::size_t, std::size_t, std::size_t>> expected, got;
      for (int pass = 0; pass < 2; ++pass) {
        for (const auto& w : all) {
          const bool whole = w.first == 0 && w.count == n;
          if (whole == (pass == 0) && w.first <= a && a < w.first + w.count) {
            expected.emplace_back(w.node, w.offset + a - w.first, w.bit + a - w.first);
          }
        }
      }
      ws.for_each(a, [&](std::size_t node, std::size_t pos, std::size_t bit) { got.emplace_back(node, pos, bit); });
      EXPECT_EQ(got, expected) << "atom " << a;
    }
  }
}

namespace {

// Shrinks, at its k-th run, the atoms listed for that run (each by half from
// above), reporting each twice.
class Shrinker : public CnNode {
 public:
  Shrinker(std::vector<AtomRange> ranges, std::vector<std::vector<std::size_t>> plan)
      : CnNode(std::move(ranges)), plan_(std::move(plan)) {}
  std::string name() const override { return "Shrinker"; }
  bool run(NodeRun& r) const override {
    if (runs_ >= plan_.size()) return true;
    for (const std::size_t pos : plan_[runs_]) {
      const std::size_t g = range_of(pos);
      Domain& d = *r.domains[ranges()[g].domain];
      const std::size_t a = ranges()[g].first + pos - offset(g);
      const Interval x = d.atom(a);
      d.set_atom(a, Interval(x.lb(), x.lb() + (x.ub() - x.lb()) / 2));
      r.changed.push_back(pos);
      r.changed.push_back(pos);  // duplicates are allowed
    }
    ++runs_;
    return true;
  }
  mutable std::size_t runs_ = 0;

 private:
  std::vector<std::vector<std::size_t>> plan_;
};

// Records what woke it (after its first run); it watches a sub-range only.
class Recorder : public CnNode {
 public:
  Recorder(std::vector<AtomRange> ranges, std::size_t first, std::size_t count) : CnNode(std::move(ranges)) {
    watch_only(0, first, count);
  }
  std::string name() const override { return "Recorder"; }
  bool run(NodeRun& r) const override {
    if (!r.all) seen.emplace_back(r.dirty.begin(), r.dirty.end());
    return true;
  }
  mutable std::vector<std::vector<std::size_t>> seen;
};

}  // namespace

TEST(ContractorNetwork, NodeIsToldItsWatchedAtomsThatShrankSortedOnce) {
  ContractorNetwork cn;
  auto x = cn.create_dom(IntervalVector(40, Interval(0, 1)), "x");
  const std::size_t dx = cn.add_domain(std::make_shared<BoxDomain>(x));
  // The shrinker acts on x[0..39]; the recorder on x[10..29], watching x[15..24] (its positions 5..14).
  const auto shrink = std::make_shared<Shrinker>(std::vector<AtomRange>{{dx, 0, 40}},
                                                 std::vector<std::vector<std::size_t>>{{3, 20, 16, 20, 24, 25, 15}});
  const auto rec = std::make_shared<Recorder>(std::vector<AtomRange>{{dx, 10, 20}}, 15, 10);
  cn.add_node(rec);
  cn.add_node(shrink);
  const ContractStats s = cn.contract();
  EXPECT_FALSE(s.empty);
  // Round 1 ran both (the recorder fresh, then the shrinker); round 2 the recorder with x[15],
  // x[16], x[20], x[24] (positions 5, 6, 10, 14), each once, sorted; not x[25]: not watched.
  ASSERT_EQ(rec->seen.size(), 1u);
  EXPECT_EQ(rec->seen[0], (std::vector<std::size_t>{5, 6, 10, 14}));
  EXPECT_EQ(s.contractor_calls, 3u);
}

namespace {

// Asks to run again (NodeRun::again) for its first `times` runs; counts its runs.
class Again : public CnNode {
 public:
  Again(std::vector<AtomRange> ranges, std::size_t times) : CnNode(std::move(ranges)), times_(times) {}
  std::string name() const override { return "Again"; }
  bool run(NodeRun& r) const override {
    ++runs;
    r.again = runs <= times_;
    return true;
  }
  mutable std::size_t runs = 0;

 private:
  std::size_t times_;
};

}  // namespace

// A node that asks to run again is queued for the next round, once, even when nothing wakes it
// (CtcEval's node after one pass that shrank something); the network stops when it stops asking.
TEST(ContractorNetwork, NodeAskingToRunAgainRunsInTheNextRound) {
  ContractorNetwork cn;
  auto x = cn.create_dom(IntervalVector(4, Interval(0, 1)), "x");
  const std::size_t dx = cn.add_domain(std::make_shared<BoxDomain>(x));
  const auto again = std::make_shared<Again>(std::vector<AtomRange>{{dx, 0, 4}}, 3);
  const auto idle = std::make_shared<Again>(std::vector<AtomRange>{{dx, 0, 4}}, 0);
  cn.add_node(again);
  cn.add_node(idle);
  const ContractStats s = cn.contract();
  EXPECT_FALSE(s.empty);
  EXPECT_EQ(again->runs, 4u);  // asked after runs 1, 2, 3
  EXPECT_EQ(idle->runs, 1u);   // nothing woke it
  EXPECT_EQ(s.iterations, 4u);
  EXPECT_EQ(s.contractor_calls, 5u);
}
