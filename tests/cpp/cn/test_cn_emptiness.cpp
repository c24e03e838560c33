// An empty network is an answer, reported with its provenance: which
// contractor emptied which domain, where (component, slice or gate, with its
// time), in words (ContractStats::emptiness) and field by field.
#include <gtest/gtest.h>

#include <memory>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"

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
