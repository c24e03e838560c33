// The network's bookkeeping of what woke a node: DirtyAtoms (one bit per node
// and watched atom, read back as sorted positions) and the per-atom lists of
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
    }
    for (const Idle& n : nodes) dirty.add_node(n);
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
      EXPECT_EQ(dirty.mark(i, g, w.first + a), first);
      ++wakes[i];
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      EXPECT_EQ(dirty.wakes(i), wakes[i]);
      std::vector<std::size_t> got;
      dirty.take(i, nodes[i], got);
      EXPECT_EQ(got, std::vector<std::size_t>(expected[i].begin(), expected[i].end()));
      EXPECT_EQ(dirty.wakes(i), 0u);
      dirty.take(i, nodes[i], got);
      EXPECT_TRUE(got.empty());
    }
  }
}

TEST(DirtyAtoms, ResetForgetsEverything) {
  detail::DirtyAtoms dirty;
  Idle node({{0, 0, 10}}, {{0, 0, 10}});
  std::vector<std::size_t> got;
  dirty.add_node(node);
  dirty.reset();
  EXPECT_TRUE(dirty.mark(0, 0, 3));
  dirty.reset();
  EXPECT_EQ(dirty.wakes(0), 0u);
  dirty.take(0, node, got);
  EXPECT_TRUE(got.empty());
  dirty.clear_nodes();
  EXPECT_EQ(dirty.nb_nodes(), 0u);
}

TEST(Watchers, ListsEveryWatchCoveringTheAtom) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    const std::size_t n = 1 + rng() % 200;
    detail::Watchers ws(n);
    std::vector<detail::Watchers::Watch> all;
    for (int k = 0; k < 25; ++k) {
      const bool whole = rng() % 4 == 0;
      const std::size_t first = whole ? 0 : rng() % n, count = whole ? n : 1 + rng() % (n - first);
      const detail::Watchers::Watch w{static_cast<std::size_t>(k), rng() % 5, first, count};
      all.push_back(w);
      ws.add(w);
    }
    for (std::size_t a = 0; a < n; ++a) {
      // Whole-domain watches first, then the others, each in the order of add().
      std::vector<std::tuple<std::size_t, std::size_t>> expected, got;
      for (int pass = 0; pass < 2; ++pass) {
        for (const auto& w : all) {
          const bool whole = w.first == 0 && w.count == n;
          if (whole == (pass == 0) && w.first <= a && a < w.first + w.count) {
            expected.emplace_back(w.node, w.range);
          }
        }
      }
      ws.for_each(a, [&](std::size_t node, std::size_t range) { got.emplace_back(node, range); });
      EXPECT_EQ(got, expected) << "atom " << a;
    }
  }
}

// A domain that gains atoms at its end: the watches of the whole domain cover them, the others
// not, and the atoms it had keep their watches.
TEST(Watchers, GrowKeepsTheWatchesAndExtendsTheWholeOnes) {
  detail::Watchers ws(10);
  ws.add({0, 1, 0, 10});  // whole
  ws.add({1, 0, 8, 2});   // the last two atoms
  ws.add({2, 3, 3, 4});
  ws.grow(14);
  const auto at = [&](std::size_t a) {
    std::vector<std::pair<std::size_t, std::size_t>> got;
    ws.for_each(a, [&](std::size_t node, std::size_t range) { got.emplace_back(node, range); });
    return got;
  };
  using P = std::vector<std::pair<std::size_t, std::size_t>>;
  EXPECT_EQ(at(4), (P{{0, 1}, {2, 3}}));
  EXPECT_EQ(at(9), (P{{0, 1}, {1, 0}}));
  EXPECT_EQ(at(13), (P{{0, 1}}));
  ws.add({3, 0, 12, 2});  // added after the growth: on the 14 atoms
  EXPECT_EQ(at(13), (P{{0, 1}, {3, 0}}));
  EXPECT_EQ(at(9), (P{{0, 1}, {1, 0}}));
}

// A node whose ranges grew is laid out again alone: its positions follow its new offsets, and
// the other nodes' bits are untouched.
TEST(DirtyAtoms, RelayoutNodeFollowsGrownRanges) {
  Idle a({{0, 0, 5}, {1, 0, 5}}, {{0, 0, 5}, {1, 0, 5}});
  Idle b({{0, 0, 5}}, {{0, 1, 2}});
  detail::DirtyAtoms dirty;
  dirty.add_node(a);
  dirty.add_node(b);
  dirty.reset();
  EXPECT_TRUE(dirty.mark(1, 0, 2));
  // Domain 0 grows from 5 to 9 atoms: a's first range (watched whole) with it, not b's watch.
  const Idle grown({{0, 0, 9}, {1, 0, 5}}, {{0, 0, 9}, {1, 0, 5}});
  dirty.relayout_node(0, grown);
  EXPECT_TRUE(dirty.mark(0, 0, 8));
  EXPECT_TRUE(dirty.mark(0, 1, 0));
  EXPECT_FALSE(dirty.mark(0, 0, 8));
  std::vector<std::size_t> got;
  dirty.take(0, grown, got);
  EXPECT_EQ(got, (std::vector<std::size_t>{8, 9}));  // range 1 now starts at position 9
  dirty.take(1, b, got);
  EXPECT_EQ(got, (std::vector<std::size_t>{2}));  // b's watch (atoms 1, 2) did not grow
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
