// TubeNode, the base of tube contractor nodes: atom encoding, dirty atoms to
// slices, change reporting (TubeChanges), argument checks naming the
// contractor; TubeContractor's node through CtcIncrement, and a new contractor
// written on the base in a few lines.
#include <gtest/gtest.h>

#include <memory>
#include <span>
#include <utility>

#include "sillage/cn/contractor_network.h"
#include "sillage/cn/tube_node.h"
#include "sillage/dynamics/ctc_increment.h"

using namespace sillage;

namespace {

// x(t) <= c on every gate: the smallest TubeNode, re-contracting only the
// slices around what changed.
class CtcGatesBelow : public NetworkCtc {
 public:
  explicit CtcGatesBelow(double c) : c_(c) {}
  std::string name() const override { return "CtcGatesBelow"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override {
    return std::make_shared<Node>(args, c_);
  }

  class Node : public TubeNode {
   public:
    Node(const std::vector<BoundDomain>& args, double c) : TubeNode("CtcGatesBelow", args), c_(c) {
      if (args.size() != 1) throw DimensionError(where() + ": expects one tube");
      x_ = whole_tubes(0, 1, "x").front();
    }
    bool run(NodeRun& r) const override {
      std::size_t first = 0, last = 0;
      if (!dirty_slices(r, 0, first, last)) return true;
      const Tube::Writer w = x_->tube().write();  // x's version steps once, when it ends
      const std::span<Interval> g = w.gates();
      const TubeChanges out = changes(r, 0);
      for (std::size_t k = first; k <= last + 1; ++k) {
        const Interval before = g[k];
        g[k] &= Interval(-1e300, c_);
        out.gate(k, before, g[k]);
        if (g[k].is_empty()) return false;
      }
      return true;
    }
    // For the test: what the base makes of a run.
    using TubeNode::dirty_slices;
    using TubeNode::dirty_time_atoms;

   private:
    std::shared_ptr<TubeDomain> x_;
    double c_;
  };

 private:
  double c_;
};

// x from 0 in [-10, 10], with increments i = 1 per slice (10 slices).
std::pair<std::shared_ptr<Tube>, std::shared_ptr<Tube>> unit_increments() {
  auto td = TDomain::create(0.0, 1.0, 0.1);
  auto x = std::make_shared<Tube>(td, Interval(-10, 10));
  x->set_gate(0, Interval(0));
  return {x, std::make_shared<Tube>(td, Interval(1))};
}

}  // namespace

TEST(TubeNode, AtomEncoding) {
  EXPECT_EQ(TubeNode::gate_atom(3), 6u);
  EXPECT_EQ(TubeNode::slice_atom(3), 7u);
  EXPECT_TRUE(TubeNode::is_slice(7));
  EXPECT_FALSE(TubeNode::is_slice(6));
  EXPECT_EQ(TubeNode::time_index(7), 3u);
  TubeData d;
  d.slices = {Interval(1), Interval(2)};
  d.gates = {Interval(10), Interval(11), Interval(12)};
  EXPECT_EQ(TubeNode::time_atom(d, 3), Interval(2));
  EXPECT_EQ(TubeNode::time_atom(d, 4), Interval(12));
}

TEST(TubeNode, DirtyAtomsBecomeSlicesAndTimeAtoms) {
  auto td = TDomain::create(0.0, 1.0, 0.1);  // 10 slices, 21 atoms
  auto x = std::make_shared<Tube>(td, Interval(-10, 10));
  auto dom = std::make_shared<TubeDomain>(x);
  const std::vector<BoundDomain> args{{dom, {0, 0, 21}}};
  const CtcGatesBelow::Node node(args, 1.0);
  const std::vector<std::shared_ptr<Domain>> domains{dom};
  std::vector<std::size_t> changed;
  const std::vector<std::size_t> dirty{4, 9};  // gate 2, slice 4
  NodeRun run{domains, 0.01, false, dirty, changed};
  std::size_t first = 99, last = 99;
  ASSERT_TRUE(node.dirty_slices(run, 0, first, last));
  EXPECT_EQ(first, 1u);  // a gate wakes both its slices
  EXPECT_EQ(last, 4u);
  bool constants = true;
  EXPECT_EQ(node.dirty_time_atoms(run, constants), (std::vector<std::size_t>{4, 8, 9, 10}));
  EXPECT_FALSE(constants);
  NodeRun all{domains, 0.01, true, {}, changed};
  ASSERT_TRUE(node.dirty_slices(all, 0, first, last));
  EXPECT_EQ(first, 0u);
  EXPECT_EQ(last, 9u);
  NodeRun none{domains, 0.01, false, {}, changed};
  EXPECT_FALSE(node.dirty_slices(none, 0, first, last));
}

TEST(TubeNode, ANewContractorInANetworkReportsWhatShrank) {
  const auto [x, i] = unit_increments();
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcIncrement>(), {x, i});   // x(t_k) = k
  cn.add(std::make_shared<CtcGatesBelow>(5.5), {x});  // but x(t_6) = 6 > 5.5: no trajectory
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.empty_contractor, "CtcGatesBelow");
  EXPECT_EQ(s.empty_atom, "gate");
  EXPECT_EQ(s.empty_atom_index, 6u);
}

TEST(TubeNode, PairNodeChecksItsArgumentsNamingTheContractor) {
  auto td = TDomain::create(0.0, 1.0, 0.1), other = TDomain::create(0.0, 1.0, 0.2);
  ContractorNetwork cn;
  const auto inc = std::make_shared<CtcIncrement>();
  try {
    cn.add(inc, {std::make_shared<Tube>(td), std::make_shared<Tube>(other)});
    FAIL();
  } catch (const DimensionError& e) {
    EXPECT_NE(std::string(e.what()).find("ContractorNetwork::add(CtcIncrement): the tubes are not on one TDomain"),
              std::string::npos);
  }
  EXPECT_THROW(cn.add(inc, {std::make_shared<Tube>(td)}), DimensionError);
  EXPECT_THROW(cn.add(inc, {std::make_shared<Tube>(td), std::make_shared<Interval>()}), DimensionError);
  EXPECT_EQ(cn.nb_dom(), 0u);
}

TEST(TubeNode, PairNodeLocatesTheEmptiness) {
  const auto [x, i] = unit_increments();
  x->set_gate(7, Interval(0));  // but x(t_7) = 7
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcIncrement>(), {x, i});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.empty_contractor, "CtcIncrement");
  EXPECT_EQ(s.empty_atom, "gate");
  EXPECT_EQ(s.empty_atom_index, 7u);
}

TEST(TubeChanges, RecordsShrinkingByMoreThanTheRatioOnly) {
  std::vector<std::size_t> out;
  const TubeChanges c(out, 100, 0.1);
  c.gate(2, Interval(0, 10), Interval(0, 9.5));   // 5%: no
  c.slice(2, Interval(0, 10), Interval(0, 5));    // atom 5
  c.gate(3, Interval(0, 10), Interval(0, 10));    // unchanged
  EXPECT_EQ(out, (std::vector<std::size_t>{105}));
  TubeChanges().gate(0, Interval(0, 1), Interval::empty());  // inactive: no-op
}
