// ContractorNetwork on tubes: pointwise constraints applied at every slice and
// gate (same result as the direct tube contraction), slice-granular waking
// (only the changed slices are contracted again), constants over time,
// tube vectors and their components, errors, emptiness, and truth kept.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <random>

#include "cn/counting_ctc.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/cn/tube_domain.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube_ctc.h"

using namespace sillage;
using sillage::test::Counting;

namespace {

std::shared_ptr<CtcFunction> ctc(const std::vector<std::string>& vars, const std::string& text) {
  return std::make_shared<CtcFunction>(Function(vars, text));
}

// A node that intersects one slice of a tube with a value (as an observation would).
class SliceObservation : public NetworkCtc {
 public:
  SliceObservation(std::size_t k, Interval y) : k_(k), y_(y) {}
  std::string name() const override { return "SliceObservation"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override {
    if (args.size() != 1 || !std::dynamic_pointer_cast<TubeDomain>(args[0].domain)) {
      throw DimensionError("SliceObservation: one tube expected");
    }
    return std::make_shared<Node>(args[0].range, 2 * k_ + 1, y_);
  }

 private:
  struct Node : CnNode {
    Node(AtomRange r, std::size_t atom, Interval y) : CnNode({r}), atom_(atom), y_(y) {}
    std::string name() const override { return "SliceObservation"; }
    bool run(NodeRun& r) const override {
      Domain& d = *r.domains[ranges()[0].domain];
      const Interval now = d.atom(atom_) & y_;
      if (now != d.atom(atom_)) {
        d.set_atom(atom_, now);
        r.changed.push_back(atom_);
      }
      return !now.is_empty();
    }
    std::size_t atom_;
    Interval y_;
  };
  std::size_t k_;
  Interval y_;
};

}  // namespace

TEST(ContractorNetworkTube, PointwiseConstraintEqualsDirectTubeContraction) {
  auto td = TDomain::create(0.0, 10.0, 0.1);
  const Tube x3(td, "t/5 + [-0.05, 0.05]"), x4(td, "[9.9, 10.1]");
  Tube v1(td, Interval(-20, 20));
  // Reference: the direct contraction of v1 = x4 cos(x3).
  Tube rx3 = x3, rx4 = x4, rv1 = v1;
  const CtcFunction c(Function({"v", "a", "b"}, "v - b*cos(a)"));
  ASSERT_TRUE(contract(c, {&rv1, &rx3, &rx4}));

  auto nx3 = std::make_shared<Tube>(x3), nx4 = std::make_shared<Tube>(x4), nv1 = std::make_shared<Tube>(v1);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(c), {nv1, nx3, nx4});
  EXPECT_EQ(cn.nb_dom(), 3u);
  const ContractStats s = cn.contract();
  EXPECT_FALSE(s.empty);
  EXPECT_EQ(*nv1, rv1);
  EXPECT_EQ(*nx3, rx3);
  EXPECT_EQ(*nx4, rx4);
  EXPECT_EQ(s.iterations, 1u);  // one node: nothing else to wake
}

// Many slices: the boxes go by chunks (one HC4 batch each), slices then
// gates; same tubes as box by box.
TEST(ContractorNetworkTube, ChunkedContractionEqualsDirectTubeContraction) {
  auto td = TDomain::create(0.0, 10.0, 0.007);  // 1429 slices, several chunks
  const Tube x(td, "sin(t) + [-0.1, 0.1]"), v(td, "cos(t) + [-0.2, 0.2]");
  Tube y(td), w(td, Interval(-1, 1));
  Tube rx = x, rv = v, ry = y, rw = w;
  const CtcFunction c(Function({"y", "w", "x", "v"}, "(y - sqrt((x - 2)^2 + 1), w - (x - 2) * v / y)"));
  ASSERT_TRUE(contract(c, {&ry, &rw, &rx, &rv}));
  auto nx = std::make_shared<Tube>(x), nv = std::make_shared<Tube>(v), ny = std::make_shared<Tube>(y),
       nw = std::make_shared<Tube>(w);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(c), {ny, nw, nx, nv});
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ(*ny, ry);
  EXPECT_EQ(*nw, rw);
  EXPECT_EQ(*nx, rx);
  EXPECT_EQ(*nv, rv);
  EXPECT_TRUE(ry.slice(500).is_bounded());
}

TEST(ContractorNetworkTube, ASliceChangeWakesOnlyThatSliceAndItsGates) {
  auto td = TDomain::create(0.0, 1.0, 0.01);  // 100 slices, 201 atoms
  auto x = std::make_shared<Tube>(td, Interval(-10, 10));
  auto y = std::make_shared<Tube>(td, Interval(-100, 100));
  const auto link = std::make_shared<Counting>(ctc({"x", "y"}, "y - 2*x"));
  ContractorNetwork cn;
  cn.add(link, {x, y});
  cn.add(std::make_shared<SliceObservation>(42, Interval(1, 2)), {x});
  const ContractStats s = cn.contract();
  // Round 1: link on all 201 atoms, the observation; round 2: link on slice
  // 42 and its two gates (which shrink x's gates 42, 43); round 3: the
  // observation again, which changes nothing.
  EXPECT_EQ(s.iterations, 3u);
  EXPECT_EQ(link->calls.load(), 201 + 3);
  EXPECT_EQ(y->slice(42), Interval(2, 4));
  EXPECT_EQ(y->gate(42), Interval(2, 4));
  EXPECT_EQ(y->gate(43), Interval(2, 4));
  EXPECT_EQ(y->slice(41), Interval(-20, 20));
  EXPECT_EQ(x->gate(42), Interval(1, 2));  // a gate lies in its slices
}

TEST(ContractorNetworkTube, ConstantOverTimeIsIntersectedOverAllSlices) {
  // x(t) = a t with x known to within 0.1 and a unknown: a ∈ ∩_t x(t)/t.
  auto td = TDomain::create(0.0, 10.0, 0.5);
  auto t = std::make_shared<Tube>(td, "t");
  auto x = std::make_shared<Tube>(td, "2*t + [-0.1, 0.1]");
  auto a = std::make_shared<Interval>(-10, 10);
  ContractorNetwork cn;
  cn.add(ctc({"x", "t", "a"}, "x - a*t"), {x, t, a});
  const ContractStats s = cn.contract();
  EXPECT_FALSE(s.empty);
  EXPECT_TRUE(a->contains(2.0));
  // The last slices ([9.5, 10]) alone give a within about 0.1/9.5 + slope spread.
  EXPECT_LT(a->diam(), 0.2) << *a;
}

TEST(ContractorNetworkTube, TubeVectorsAndComponentsAreLiveDomains) {
  auto td = TDomain::create(0.0, 2.0, 0.25);
  auto p = std::make_shared<TubeVector>(td, 2);
  (*p)[0] = Tube(td, "t");
  auto s = std::make_shared<Tube>(td, Interval());
  ContractorNetwork cn;
  cn.add(ctc({"y", "x"}, "y - 2*x"), {DomainRef::component(p, 1), DomainRef::component(p, 0)});
  cn.add(ctc({"s", "x", "y"}, "s - x - y"), {s, p});  // the same component tubes again
  EXPECT_EQ(cn.nb_dom(), 3u);
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ((*p)[1].slice(1), Interval(0.5, 1.0));  // contracted in place, in the vector
  EXPECT_EQ(s->slice(1), Interval(0.75, 1.5));
  EXPECT_EQ(s->gate(8), Interval(6.0));
}

TEST(ContractorNetworkTube, Errors) {
  auto td = TDomain::create(0.0, 1.0, 0.1), other = TDomain::create(0.0, 1.0, 0.2);
  auto x = std::make_shared<Tube>(td), y = std::make_shared<Tube>(other);
  ContractorNetwork cn;
  EXPECT_THROW(cn.add(ctc({"a", "b"}, "a - b"), {x}), DimensionError);           // one variable given
  EXPECT_THROW(cn.add(ctc({"a", "b"}, "a - b"), {x, y}), DimensionError);        // two TDomains
  EXPECT_THROW(cn.add(ctc({"a"}, "a"), {DomainRef(std::shared_ptr<Domain>(std::make_shared<TubeDomain>(x)), 0, 3)}),
               DimensionError);  // part of a tube
  EXPECT_EQ(cn.nb_dom(), 0u);
  EXPECT_THROW(DomainRef::component(std::make_shared<TubeVector>(td, 2), 2), DimensionError);
  cn.add(ctc({"a"}, "a"), {x});
  td->sample(0.05);  // changes the layout behind the network
  try {
    cn.contract();
    FAIL();
  } catch (const DimensionError& e) {
    EXPECT_NE(std::string(e.what()).find("slices"), std::string::npos) << e.what();
  }
}

TEST(ContractorNetworkTube, InconsistencyEmptiesAndIsReported) {
  auto td = TDomain::create(0.0, 1.0, 0.1);
  auto x = std::make_shared<Tube>(td, Interval(0, 1));
  ContractorNetwork cn;
  cn.add(ctc({"a"}, "a - 5"), {x});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_NE(s.empty_domain.find("Tube"), std::string::npos) << s.empty_domain;
  EXPECT_TRUE(x->is_empty());
}

TEST(ContractorNetworkTube, DeadReckoningNetworkKeepsTheTruth) {
  // (3.18) on [0, 8]: v = x4 (cos x3, sin x3) with random headings and speeds
  // sampled from inside the inputs; every contracted tube keeps the truth.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 10; ++trial) {
    const double a = u(rng), b = 1 + 0.2 * u(rng), c = 10 + u(rng);
    auto td = TDomain::create(0.0, 8.0, 0.05);
    const std::string heading = std::to_string(a) + " + " + std::to_string(b) + "*sin(t/3)";
    auto x3 = std::make_shared<Tube>(td, heading + " + [-0.01, 0.01]");
    auto x4 = std::make_shared<Tube>(td, std::to_string(c) + " + [-0.1, 0.1]");
    auto v = std::make_shared<TubeVector>(td, 2);
    ContractorNetwork cn;
    cn.add(ctc({"v1", "x3", "x4"}, "v1 - x4*cos(x3)"), {DomainRef::component(v, 0), x3, x4});
    cn.add(ctc({"v2", "x3", "x4"}, "v2 - x4*sin(x3)"), {DomainRef::component(v, 1), x3, x4});
    EXPECT_FALSE(cn.contract().empty);
    const Trajectory v1(std::to_string(c) + "*cos(" + heading + ")", td->t0_tf());
    const Trajectory v2(std::to_string(c) + "*sin(" + heading + ")", td->t0_tf());
    EXPECT_TRUE(v->contains({v1, v2}));
    EXPECT_LT(v->max_thickness(), 1.0);
  }
}

namespace {

// A node on a whole tube that asks to be woken only by atoms [0, 20): counts its runs.
class PartialWatch : public NetworkCtc {
 public:
  std::string name() const override { return "PartialWatch"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override {
    return std::make_shared<Node>(args[0].range, runs);
  }
  std::shared_ptr<std::atomic<int>> runs = std::make_shared<std::atomic<int>>(0);

 private:
  struct Node : CnNode {
    Node(AtomRange r, std::shared_ptr<std::atomic<int>> runs) : CnNode({r}), runs_(std::move(runs)) {
      watch_only(0, 0, 20);
    }
    std::string name() const override { return "PartialWatch"; }
    bool run(NodeRun&) const override {
      ++*runs_;
      return true;
    }
    std::shared_ptr<std::atomic<int>> runs_;
  };
};

}  // namespace

TEST(ContractorNetworkTube, NodesWatchingPartOfATubeAreWokenOnlyThere) {
  auto td = TDomain::create(0.0, 1.0, 0.01);
  auto x = std::make_shared<Tube>(td, Interval(-10, 10));
  const auto far = std::make_shared<PartialWatch>(), near = std::make_shared<PartialWatch>();
  ContractorNetwork cn;
  cn.add(far, {x});
  cn.add(std::make_shared<SliceObservation>(42, Interval(1, 2)), {x});  // atom 85: outside [0, 20)
  cn.contract();
  EXPECT_EQ(far->runs->load(), 1);  // round 1 only
  ContractorNetwork cn2;
  auto y = std::make_shared<Tube>(td, Interval(-10, 10));
  cn2.add(near, {y});
  cn2.add(std::make_shared<SliceObservation>(3, Interval(1, 2)), {y});  // atom 7: inside
  cn2.contract();
  EXPECT_EQ(near->runs->load(), 2);
}
