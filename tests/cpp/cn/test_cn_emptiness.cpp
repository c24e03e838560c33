// An empty network is an answer, reported with its provenance: which
// contractor emptied which domain, where (component, slice or gate, with its
// time), in words (ContractStats::emptiness) and field by field.
#include <gtest/gtest.h>

#include <memory>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;

namespace {

std::shared_ptr<CtcFunction> ctc(const std::vector<std::string>& vars, const std::string& text) {
  return std::make_shared<CtcFunction>(Function(vars, text));
}

}  // namespace

TEST(ContractorNetworkEmptiness, IntervalNetworkNamesContractorAndDomain) {
  ContractorNetwork cn;
  auto x = cn.create_dom(Interval(0, 1), "x");
  auto y = cn.create_dom(Interval(2, 3), "y");
  cn.add(ctc({"a", "b"}, "a - b"), {x, y});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.emptiness, "CtcFunction(a - b) emptied interval 'x'");
  EXPECT_EQ(s.empty_contractor, "CtcFunction(a - b)");
  EXPECT_EQ(s.empty_domain, "domain 0 (Interval)");
  EXPECT_EQ(s.empty_domain_index, 0u);
  EXPECT_EQ(s.empty_domain_name, "x");
  EXPECT_EQ(s.empty_atom, "");
  EXPECT_TRUE(x->is_empty());
}

// A contractor named after what it stands for (a measurement's row) is named
// so in the emptiness, whichever domain it emptied.
TEST(ContractorNetworkEmptiness, NamedContractors) {
  ContractorNetwork cn;
  auto x = cn.create_dom(Interval(0, 1), "x");
  auto y = cn.create_dom(Interval(2, 3), "y");
  cn.add(ctc({"a", "b"}, "a - b"), {x, y});
  cn.set_ctc_name(0, "ranges line 12");
  EXPECT_THROW(cn.set_ctc_name(1, "none"), Error);
  EXPECT_THROW(cn.set_ctc_name(0, ""), Error);
  const ContractStats s = cn.contract();
  EXPECT_EQ(s.emptiness, "CtcFunction(a - b) (ranges line 12) emptied interval 'x'");
  EXPECT_EQ(s.empty_contractor, "CtcFunction(a - b) (ranges line 12)");
}

TEST(ContractorNetworkEmptiness, UnnamedDomainsAndBoxComponents) {
  ContractorNetwork cn;
  auto p = std::make_shared<IntervalVector>(IntervalVector{{0, 1}, {0, 1}});
  cn.add(ctc({"a", "b"}, "b - 3"), {p});
  ContractStats s = cn.contract();
  EXPECT_EQ(s.emptiness, "CtcFunction(b - 3) emptied domain 0 (IntervalVector(2)) at component 0");
  // Named afterwards; now empty on input.
  cn.set_name(p, "p");
  s = cn.contract();
  EXPECT_EQ(s.emptiness, "box 'p' was empty on input at component 0");
  EXPECT_EQ(s.empty_contractor, "");
  EXPECT_EQ(s.empty_atom, "component");
  EXPECT_THROW(cn.set_name(p, ""), Error);
}

TEST(ContractorNetworkEmptiness, EmptyOnInput) {
  ContractorNetwork cn;
  auto x = cn.create_dom(Interval(0, 1));
  auto rho = cn.create_dom(Interval::empty(), "rho");
  cn.add(ctc({"a", "b"}, "a - b"), {x, rho});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.emptiness, "interval 'rho' was empty on input");
  EXPECT_EQ(s.contractor_calls, 0u);
  EXPECT_EQ(*x, Interval(0, 1));
}

TEST(ContractorNetworkEmptiness, CtcDerivNamesTheGateWhereTheTubeBecomesInconsistent) {
  auto td = TDomain::create(0.0, 6.0, 1.0);
  auto x = std::make_shared<Tube>(td), v = std::make_shared<Tube>(td, Interval(1));
  x->set_gate(0, Interval(0));
  x->set_gate(3, Interval(0, 0.5));  // x(3) = 3 if x' = 1
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.set_name(x, "x");
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.emptiness, "CtcDeriv emptied tube 'x' at gate 3 (t = 3)");
  EXPECT_EQ(s.empty_contractor, "CtcDeriv");
  EXPECT_EQ(s.empty_atom, "gate");
  EXPECT_EQ(s.empty_atom_index, 3u);
  EXPECT_EQ(s.empty_time, Interval(3));
}

TEST(ContractorNetworkEmptiness, CtcDerivNamesTheSlice) {
  auto td = TDomain::create(0.0, 6.0, 1.0);
  std::vector<Interval> slices(6), gates(7);
  gates[0] = Interval(0);
  slices[1] = Interval(5, 6);  // |x| <= 2 over slice 1, whose gates are free
  auto x = std::make_shared<Tube>(td, slices, gates), v = std::make_shared<Tube>(td, Interval(-1, 1));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.set_name(x, "x");
  const ContractStats s = cn.contract();
  EXPECT_EQ(s.emptiness, "CtcDeriv emptied tube 'x' at slice 1 [1, 2]");
  EXPECT_EQ(s.empty_time, Interval(1, 2));
}

TEST(ContractorNetworkEmptiness, CtcEvalWithAnImpossibleObservation) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  auto y = std::make_shared<Tube>(td, "t");
  auto t = std::make_shared<Interval>(4.25, 4.75);
  auto z = std::make_shared<Interval>(100, 101);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcEval>(), {t, z, y});
  cn.set_name(y, "y");
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.emptiness, "CtcEval emptied tube 'y' at slice 4 [4, 5] for t in [4.25, 4.75]");
  EXPECT_EQ(s.empty_atom, "slice");
  EXPECT_EQ(s.empty_atom_index, 4u);
}

TEST(ContractorNetworkEmptiness, PointwiseConstraintOnATubeNamesTheSlice) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  auto x = std::make_shared<Tube>(td, "t");
  ContractorNetwork cn;
  cn.add(ctc({"a"}, "a - 2.5"), {x});  // x(t) = 2.5 for all t: impossible on slice 0
  const ContractStats s = cn.contract();
  EXPECT_EQ(s.emptiness, "CtcFunction(a - 2.5) emptied domain 0 (Tube(4 slices)) at slice 0 [0, 1]");
}

TEST(ContractorNetworkEmptiness, TubeVectorComponentsAreNamedByIndex) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  auto p = std::make_shared<TubeVector>(td, 2, Interval(0, 1));
  ContractorNetwork cn;
  cn.add(ctc({"a", "b"}, "b - 7"), {p});
  cn.set_name(p, "p");
  EXPECT_EQ(cn.domain_name(1), "p[1]");
  EXPECT_EQ(cn.contract().emptiness, "CtcFunction(b - 7) emptied tube 'p[0]' at slice 0 [0, 1]");
}

// A tube whose gate misses a neighbouring slice holds no continuous
// trajectory: no solution before any contractor runs, with the gate and the
// slice named, valued and timed. The tube is left as given (as an empty
// domain is), so every contract() says it again.
TEST(ContractorNetworkEmptiness, AGateOffItsSliceIsInconsistentInput) {
  auto td = TDomain::create(0.0, 2.0, 0.5);
  std::vector<Interval> slices(4), gates(5);
  slices[2] = Interval(0, 1);
  gates[3] = Interval(5, 6);
  auto x = std::make_shared<Tube>(td, slices, gates), v = std::make_shared<Tube>(td, Interval(-1, 1));
  const Tube given = *x;
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.set_name(x, "x");
  for (int run = 0; run < 2; ++run) {
    const ContractStats s = cn.contract();
    EXPECT_TRUE(s.empty);
    EXPECT_EQ(s.emptiness,
              "tube 'x': gate 3 [5, 6] at t = 1.5 does not meet slice 2 [0, 1] ([1, 1.5]): "
              "no continuous trajectory through it (inconsistent input)");
    EXPECT_EQ(s.contractor_calls, 0u);
    EXPECT_EQ(s.empty_contractor, "");
    EXPECT_EQ(s.empty_node, kNoAtom);
    EXPECT_EQ(s.empty_domain, "domain 0 (Tube(4 slices))");
    EXPECT_EQ(s.empty_domain_name, "x");
    EXPECT_EQ(s.empty_atom, "gate");
    EXPECT_EQ(s.empty_atom_index, 3u);
    EXPECT_EQ(s.empty_time, Interval(1.5));
    EXPECT_EQ(s.empty_atom_value, Interval(5, 6));
    EXPECT_EQ(s.disjoint_atom, "slice");
    EXPECT_EQ(s.disjoint_atom_index, 2u);
    EXPECT_EQ(s.disjoint_time, Interval(1, 1.5));
    EXPECT_EQ(s.disjoint_value, Interval(0, 1));
  }
  EXPECT_EQ(*x, given);
}

// The network's own check: whatever the contractors (here one that never
// compares a gate with its slices), a gate off its slice, the first one or
// one before its slice, is found.
TEST(ContractorNetworkEmptiness, AGateOffItsSliceWhateverTheContractors) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  std::vector<Interval> slices(4, Interval(0, 1)), gates(5, Interval(0, 1));
  gates[0] = Interval(2);
  auto p = std::make_shared<TubeVector>(std::vector<Tube>{Tube(td, Interval(0, 1)), Tube(td, slices, gates)});
  ContractorNetwork cn;
  cn.add(ctc({"a", "b"}, "a - b"), {p});
  ContractStats s = cn.contract();
  EXPECT_EQ(s.emptiness,
            "domain 1 (Tube(4 slices), component 1 of a TubeVector): gate 0 [2, 2] at t = 0 does not meet slice 0 "
            "[0, 1] ([0, 1]): no continuous trajectory through it (inconsistent input)");
  EXPECT_EQ(s.disjoint_atom_index, 0u);
  gates[0] = Interval(1);
  slices[1] = Interval(-3, 1);
  gates[2] = Interval(-3);  // meets slice 1, not slice 2
  (*p)[1] = Tube(td, slices, gates);
  cn.set_name(p, "p");
  s = cn.contract();
  EXPECT_EQ(s.emptiness,
            "tube 'p[1]': gate 2 [-3, -3] at t = 2 does not meet slice 2 [0, 1] ([2, 3]): "
            "no continuous trajectory through it (inconsistent input)");
}

// In time order, an empty slice or gate and a gate off its slice are both no
// solution on input; the earliest is named.
TEST(ContractorNetworkEmptiness, TheEarliestFlawOfATubeIsNamed) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  std::vector<Interval> slices(4, Interval(0, 1)), gates(5, Interval(0, 1));
  slices[1] = Interval::empty();
  gates[3] = Interval(7);
  auto x = std::make_shared<Tube>(td, slices, gates);
  ContractorNetwork cn;
  cn.add(ctc({"a"}, "a"), {x});
  cn.set_name(x, "x");
  ContractStats s = cn.contract();
  EXPECT_EQ(s.emptiness, "tube 'x' was empty on input at slice 1 [1, 2]");
  EXPECT_EQ(s.disjoint_atom, "");
  EXPECT_TRUE(s.empty_atom_value.is_empty());
  slices[1] = Interval(0, 1);
  gates[4] = Interval::empty();
  *x = Tube(td, slices, gates);
  EXPECT_EQ(cn.contract().emptiness,
            "tube 'x': gate 3 [7, 7] at t = 3 does not meet slice 2 [0, 1] ([2, 3]): "
            "no continuous trajectory through it (inconsistent input)");
}

// The pass goes by blocks of slices: a flaw anywhere is found, at the edges
// of a block too (a gate there sits between two blocks).
TEST(ContractorNetworkEmptiness, AFlawDeepInALongTube) {
  auto td = TDomain::create(0.0, 3000.0, 1.0);
  const auto first_flaw = [&](std::size_t k, const Interval& gate) {
    auto x = std::make_shared<Tube>(td, Interval(0, 1));
    x->set_gate(k, gate);
    ContractorNetwork cn;
    cn.set_name(x, "x");
    return cn.contract();
  };
  for (const std::size_t k : {1u, 1023u, 1024u, 1025u, 2999u, 3000u}) {
    const ContractStats s = first_flaw(k, Interval(2));
    EXPECT_EQ(s.empty_atom_index, k);
    EXPECT_EQ(s.disjoint_atom_index, k - 1);
    EXPECT_EQ(first_flaw(k, Interval::empty()).emptiness,
              "tube 'x' was empty on input at gate " + std::to_string(k) + " (t = " + std::to_string(k) + ")");
  }
  EXPECT_FALSE(first_flaw(0, Interval(1)).empty);
}
