// The network between contractions (online use): update() contracts only
// what changed (new contractors, atoms touched from outside), relayout()
// follows a TDomain that grew or forgot, retire() removes contractors.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "cn/counting_ctc.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/cn/tube_node.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/error.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;
using sillage::test::Counting;

namespace {

std::shared_ptr<Counting> counting(const std::vector<std::string>& vars, const std::string& text) {
  return std::make_shared<Counting>(std::make_shared<CtcFunction>(Function(vars, text)));
}

}  // namespace

TEST(CnOnline, UpdateAtAFixedPointRunsNothing) {
  ContractorNetwork cn;
  auto x = cn.create_dom(Interval(0, 10), "x");
  auto y = cn.create_dom(Interval(0, 10), "y");
  cn.add(counting({"x", "y"}, "x - y - 1"), {x, y});
  cn.contract();
  const ContractStats s = cn.update();
  EXPECT_EQ(s.contractor_calls, 0u);
  EXPECT_EQ(s.summary.status, Status::Converged);
}

TEST(CnOnline, UpdateRunsTheNewContractorsAndWhatTheyWake) {
  ContractorNetwork cn;
  auto x = cn.create_dom(Interval(0, 10), "x");
  auto y = cn.create_dom(Interval(0, 10), "y");
  auto z = cn.create_dom(Interval(0, 10), "z");
  auto far = counting({"z"}, "z - 5");
  auto link = counting({"x", "y"}, "x - y - 1");
  cn.add(far, {z});
  cn.add(link, {x, y});
  cn.contract();
  far->calls = 0;
  link->calls = 0;
  cn.add(counting({"y"}, "y - 2"), {y});  // y = 2 pins x = 3
  const ContractStats s = cn.update();
  EXPECT_EQ(*x, Interval(3, 3));
  EXPECT_EQ(far->calls, 0);  // not reached
  EXPECT_EQ(link->calls, 1);
  EXPECT_EQ(s.contractor_calls, 2u);
}

TEST(CnOnline, TouchedWakesTheContractorsOfTheSlicesItNames) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  auto x = std::make_shared<Tube>(td, Interval(0, 10));
  auto y = std::make_shared<Tube>(td, Interval(0, 10));
  ContractorNetwork cn;
  auto link = counting({"x", "y"}, "x - y");
  cn.add(link, {x, y});
  cn.contract();
  link->calls = 0;
  x->write().slices()[7] = Interval(1, 2);  // an input written from outside
  cn.touched(x, Interval(7.2, 7.8));
  cn.update();
  EXPECT_EQ(y->slice(7), Interval(1, 2));
  EXPECT_EQ(y->slice(6), Interval(0, 10));
  EXPECT_LE(link->calls, 3);  // slice 7 and its two gates, not 21 atoms
  EXPECT_THROW(cn.touched(x, Interval::empty()), Error);
  EXPECT_THROW(cn.touched(std::make_shared<Interval>(1, 2)), Error);  // not in the network
}

TEST(CnOnline, RelayoutFollowsATDomainThatGrows) {
  auto td = TDomain::create({0.0, 1.0});
  auto x = std::make_shared<TubeVector>(td, 1);
  auto v = std::make_shared<TubeVector>(td, 1, Interval(1, 2));
  x->set_gate(0, IntervalVector{Interval(0, 0)});
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.contract();
  EXPECT_EQ((*x)[0].gate(1), Interval(1, 2));
  td->extend(3.0);
  EXPECT_THROW(cn.update(), DimensionError);  // the layout is stale until relayout()
  cn.relayout();
  (*v)[0].write().slices()[1] = Interval(1, 2);
  cn.touched(v, Interval(1, 3));
  const ContractStats s = cn.update();
  EXPECT_FALSE(s.empty);
  EXPECT_EQ((*x)[0].gate(2), Interval(3, 6));
  td->forget_before(1.0);
  cn.relayout();
  EXPECT_EQ(cn.update().contractor_calls, 0u);
  EXPECT_EQ((*x)[0].gate(0), Interval(1, 2));
}

TEST(CnOnline, RetireRemovesContractorsAndTheDomainsOnlyTheyUsed) {
  ContractorNetwork cn;
  auto x = cn.create_dom(Interval(0, 10), "x");
  auto y = cn.create_dom(Interval(0, 10), "y");
  auto z = std::make_shared<Interval>(0, 10);
  cn.add(counting({"x", "y"}, "x - y"), {x, y});
  cn.add(counting({"y", "z"}, "y - z"), {y, z});
  cn.add(counting({"x"}, "x - 4"), {x});
  cn.set_ctc_name(2, "x fix");
  cn.contract();
  EXPECT_EQ(cn.nb_dom(), 3u);
  cn.retire({1});
  EXPECT_EQ(cn.nb_ctc(), 2u);
  EXPECT_EQ(cn.nb_dom(), 2u);  // z was used by the retired one only
  EXPECT_EQ(cn.domain_name(0), "x");
  EXPECT_EQ(*z, Interval(4, 4));  // the object keeps its value
  cn.add(counting({"x"}, "x - 5"), {x});  // inconsistent: named by the right contractor
  const ContractStats s = cn.update();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.empty_node, 2u);
  EXPECT_THROW(cn.retire({7}), Error);
}

namespace {

// A node on whole tubes that follows appends and records, per run, the
// positions that woke it; its contractor counts the nodes it made.
class RecordingNode : public TubeNode {
 public:
  RecordingNode(const std::vector<BoundDomain>& args, std::vector<std::vector<std::size_t>>& seen)
      : TubeNode("Recording", args), seen_(seen) {
    whole_tubes(0, nb_args(), "the arguments");
  }
  bool follows_appends() const override { return true; }
  bool run(NodeRun& r) const override {
    if (!r.all) seen_.emplace_back(r.dirty.begin(), r.dirty.end());
    return true;
  }
  std::size_t position(std::size_t range, std::size_t atom) const { return offset(range) + atom; }

 private:
  std::vector<std::vector<std::size_t>>& seen_;
};

class Recording : public NetworkCtc {
 public:
  std::string name() const override { return "Recording"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override {
    ++made;
    auto node = std::make_shared<RecordingNode>(args, seen);
    last = node;
    return node;
  }
  mutable std::size_t made = 0;
  mutable std::vector<std::vector<std::size_t>> seen;
  mutable std::shared_ptr<const RecordingNode> last;
};

}  // namespace

// A TDomain that grows at its end: the nodes that follow appends are kept (not made again), their
// ranges, watches and dirty bits grown in place, so that an atom of a new slice wakes them with its
// position on the grown layout.
TEST(CnOnline, RelayoutGrowsTheNodesThatFollowAppendsInPlace) {
  auto td = TDomain::create({0.0, 1.0});
  auto x = std::make_shared<Tube>(td, Interval(0, 10));
  auto y = std::make_shared<Tube>(td, Interval(0, 10));
  ContractorNetwork cn;
  const auto rec = std::make_shared<Recording>();
  cn.add(rec, {x, y});
  cn.add(std::make_shared<CtcDeriv>(), {x, y});  // follows appends too
  cn.contract();
  for (int step = 2; step <= 6; ++step) {
    td->extend(static_cast<double>(step));
    cn.relayout();
    const std::size_t k = td->nb_slices() - 1;  // the new slice
    y->write().slices()[k] = Interval(1, 2);
    rec->seen.clear();
    cn.touched(y, Interval(step - 0.5, step - 0.25));  // the new slice alone: its atom 2k + 1
    cn.update();
    ASSERT_EQ(rec->made, 1u);  // the same node all along
    ASSERT_FALSE(rec->seen.empty());
    // y's new slice, then what CtcDeriv shrank in x: the new gate (and slice).
    const std::size_t pos = rec->last->position(1, 2 * k + 1);
    EXPECT_NE(std::find(rec->seen.front().begin(), rec->seen.front().end(), pos), rec->seen.front().end())
        << "step " << step;
    EXPECT_EQ(pos, (2 * k + 3) + (2 * k + 1));  // x's range now has 2k + 3 atoms
  }
  // Forgetting the past shifts the node too (not made again): the slices
  // kept wake it at their new positions.
  td->forget_before(3.0);
  td->extend(7.0);
  cn.relayout();
  EXPECT_EQ(rec->made, 1u);
  ASSERT_EQ(td->nb_slices(), 4u);  // [3, 4] ... [6, 7]
  for (std::size_t k : {0u, 1u, 3u}) {
    y->write().slices()[k] &= Interval(1, 1.5 + 0.1 * static_cast<double>(k));
    rec->seen.clear();
    cn.touched(y, Interval(td->t(k) + 0.25, td->t(k) + 0.5));
    cn.update();
    ASSERT_FALSE(rec->seen.empty());
    const std::size_t pos = rec->last->position(1, 2 * k + 1);
    EXPECT_NE(std::find(rec->seen.front().begin(), rec->seen.front().end(), pos), rec->seen.front().end())
        << "slice " << k;
    EXPECT_EQ(pos, 9u + (2 * k + 1));  // x's range now has 2 * 4 + 1 atoms
  }
  // CtcDeriv followed as well: x' = y in [1, 2] on the slices kept, bit for bit as a network made now.
  ContractorNetwork fresh;
  auto x2 = std::make_shared<Tube>(*x);
  auto y2 = std::make_shared<Tube>(*y);
  fresh.add(std::make_shared<CtcDeriv>(), {x2, y2});
  fresh.contract();
  cn.contract();
  EXPECT_EQ(x->gates().size(), x2->gates().size());
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) EXPECT_EQ(x->gate(k), x2->gate(k)) << "gate " << k;
}

// Retiring contractors on a TDomain that forgot its past: the nodes kept are
// shifted in place, the domains only the retired ones used are dropped, and
// the network contracts as one built anew on what is left.
TEST(CnOnline, RetireAfterForgettingShiftsTheNodesKept) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  auto x = std::make_shared<Tube>(td, Interval(-100, 100));
  auto v = std::make_shared<Tube>(td, Interval(1, 2));
  x->set_gate(0, Interval(0));
  ContractorNetwork cn;
  const auto rec = std::make_shared<Recording>();
  cn.add(rec, {x, v});
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  std::vector<std::shared_ptr<Interval>> ts, zs;
  for (int i = 1; i <= 8; ++i) {  // x(t_i) in [z_i], t_i within a slice
    ts.push_back(std::make_shared<Interval>(i + 0.2, i + 0.4));
    zs.push_back(std::make_shared<Interval>(-100, 100));
    cn.add(std::make_shared<CtcEval>(), {ts.back(), zs.back(), x, v});
  }
  cn.contract();
  const std::size_t domains = cn.nb_dom();
  td->forget_before(4.0);  // slices [0, 4) gone: the evaluations at 1.2, 2.2, 3.2 retire
  td->extend(11.0);
  cn.retire({2, 3, 4});
  EXPECT_EQ(rec->made, 1u);  // shifted, not made again
  EXPECT_EQ(cn.nb_ctc(), 7u);
  EXPECT_EQ(cn.nb_dom(), domains - 6);  // their times and values dropped
  // A tighter value at 5.3 reaches x there through the shifted evaluation node.
  *zs[4] = Interval(7, 7.5);
  cn.touched(zs[4]);
  EXPECT_FALSE(cn.update().empty);
  ASSERT_EQ(td->t(1), 5.0);
  EXPECT_TRUE(x->gate(1).is_subset(Interval(6.1, 7.4))) << x->gate(1);  // x(5) = x(t) - [1, 2](t - 5)
  // The same network built anew on the tubes as they are: the same values, bit for bit.
  auto x2 = std::make_shared<Tube>(*x);
  auto v2 = std::make_shared<Tube>(*v);
  ContractorNetwork fresh;
  fresh.add(std::make_shared<CtcDeriv>(), {x2, v2});
  for (std::size_t i = 3; i < 8; ++i) fresh.add(std::make_shared<CtcEval>(), {ts[i], zs[i], x2, v2});
  fresh.contract();
  cn.contract();
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) EXPECT_EQ(x->gate(k), x2->gate(k)) << "gate " << k;
}

// update() checks a tube touched at some times there only (the rest was checked before), and
// still finds an input written empty there, or a gate written off its slice, and names it.
TEST(CnOnline, TouchedAtomsAreCheckedForEmptinessOnInput) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  auto x = std::make_shared<Tube>(td, Interval(0, 10));
  auto y = std::make_shared<Tube>(td, Interval(0, 10));
  ContractorNetwork cn;
  cn.add(counting({"x", "y"}, "x - y"), {x, y});
  cn.set_name(x, "x");
  cn.contract();
  x->write().slices()[7] = Interval::empty();
  cn.touched(x, Interval(7.2, 7.8));
  ContractStats s = cn.update();
  ASSERT_TRUE(s.empty);
  EXPECT_NE(s.emptiness.find("slice 7"), std::string::npos) << s.emptiness;
  EXPECT_EQ(s.contractor_calls, 0u);  // found before any contractor ran
  // Domain::empty_on_input on atoms: the slices holding them with their gates.
  x->write().slices()[7] = Interval(1, 2);
  x->write().gates()[3] = Interval(20, 21);  // off slices 2 and 3
  TubeDomain dom(x);
  EXPECT_FALSE(dom.empty_on_input(9, 12).empty);  // slices 4, 5: nothing wrong
  EXPECT_TRUE(dom.empty_on_input(7, 8).empty);    // slice 3 (atom 7) with its gate 3
  EXPECT_TRUE(dom.empty_on_input(6, 7).empty);    // gate 3 (atom 6)
  EXPECT_EQ(dom.empty_on_input(4, 9).atom, 6u);   // the first flaw in time order
  EXPECT_TRUE(dom.empty_on_input().empty);
}

// Between two relayouts update() checks the layouts of the contractors it runs
// only: a box resized behind the network's back is still an error, found
// before a contractor reads it, not a contraction on the wrong atoms.
TEST(CnOnline, UpdateFindsABoxResizedBetweenRelayouts) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  auto x = std::make_shared<Tube>(td, Interval(0, 10));
  auto b = std::make_shared<IntervalVector>(IntervalVector{{0, 10}, {0, 10}});
  ContractorNetwork cn;
  cn.add(counting({"a", "b"}, "a - b"), {b});
  cn.add(std::make_shared<CtcDeriv>(), {x, x});
  cn.contract();
  td->extend(5.0);
  cn.relayout();
  EXPECT_FALSE(cn.update().empty);  // nothing moved since the relayout
  *b = IntervalVector(3, Interval(0, 10));
  cn.touched(b);
  EXPECT_THROW(cn.update(), DimensionError);
}

// As many slices forgotten as appended is a change of layout too: the atoms
// moved although their number did not.
TEST(CnOnline, ForgettingAsManyAsAppendedIsALayoutChange) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  auto x = std::make_shared<Tube>(td, Interval(0, 10));
  auto v = std::make_shared<Tube>(td, Interval(1, 2));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.contract();
  td->extend(5.0);
  td->forget_before(1.0);
  ASSERT_EQ(td->nb_slices(), 4u);
  EXPECT_THROW(cn.update(), DimensionError);  // stale until relayout()
  cn.relayout();
  EXPECT_FALSE(cn.update().empty);
}

// A tube moved to another TDomain and touched between two relayouts: its
// atoms are not those the nodes watch, an error before any of them is woken.
TEST(CnOnline, UpdateFindsATouchedTubeOnAnotherTDomain) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  auto x = std::make_shared<Tube>(td, Interval(0, 10));
  auto v = std::make_shared<Tube>(td, Interval(1, 2));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.contract();
  *v = Tube(TDomain::create(0.0, 4.0, 0.1), Interval(1, 2));  // 40 slices, not 4
  cn.touched(v, Interval(3.5, 4.0));
  EXPECT_THROW(cn.update(), DimensionError);
}
