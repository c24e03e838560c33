// CtcDeriv and CtcEval as ContractorNetwork contractors: same result as the
// direct calls, propagation through pointwise contractors, an observation
// at an uncertain time propagated both ways, the fronts beyond [t] left to
// the network's CtcDeriv, argument errors.
#include <gtest/gtest.h>

#include <cmath>

#include "sillage/cn/contractor_network.h"
#include "sillage/cn/tube_domain.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/error.h"
#include "sillage/tube/trajectory.h"

using namespace sillage;

TEST(TubeNodes, DerivInTheNetworkEqualsTheDirectCall) {
  auto td = TDomain::create(0.0, 5.0, 0.1);
  Tube x(td), v(td, "cos(t) + [-0.1, 0.1]");
  x.set_gate(0, Interval(0.0));
  Tube direct = x;
  CtcDeriv().contract(direct, v);
  auto nx = std::make_shared<Tube>(x), nv = std::make_shared<Tube>(v);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {nx, nv});
  const ContractStats s = cn.contract();
  EXPECT_FALSE(s.empty);
  EXPECT_EQ(*nx, direct);
  EXPECT_EQ(s.iterations, 1u);
}

TEST(TubeNodes, ObservationAtAnUncertainTimeIsPropagatedBothWays) {
  // x' = v, v = cos(t) ± 0.05, x(t*) = sin(t*) observed with t* = 3 known to ±0.05.
  auto td = TDomain::create(0.0, 6.0, 0.05);
  auto x = std::make_shared<Tube>(td);
  auto v = std::make_shared<Tube>(td, "cos(t) + [-0.05, 0.05]");
  auto t = std::make_shared<Interval>(2.95, 3.05);
  auto z = std::make_shared<Interval>(std::sin(3.0) - 1e-3, std::sin(3.0) + 1e-3);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  cn.add(std::make_shared<CtcEval>(), {t, z, x, v});
  const ContractStats s = cn.contract();
  EXPECT_FALSE(s.empty);
  EXPECT_TRUE(x->contains(Trajectory("sin(t)", td->t0_tf())));
  EXPECT_TRUE(t->contains(3.0));
  // Bounded everywhere from one observation (forward and backward).
  EXPECT_LT(x->gate(0).diam(), 1.0);
  EXPECT_LT(x->gate(td->nb_slices()).diam(), 1.0);
  EXPECT_LT(x->gate(60).diam(), 0.2);  // t = 3
}

TEST(TubeNodes, VectorEvaluationAndPointwiseConstraints) {
  // p' = (cos h, sin h) · s, heading and speed known: one position fix at t in [4, 4.1].
  auto td = TDomain::create(0.0, 8.0, 0.05);
  auto p = std::make_shared<TubeVector>(td, 2);
  auto v = std::make_shared<TubeVector>(td, 2);
  auto h = std::make_shared<Tube>(td, "t/4 + [-0.01, 0.01]");
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(Function({"v", "h"}, "v - cos(h)")), {DomainRef::component(v, 0), h});
  cn.add(std::make_shared<CtcFunction>(Function({"v", "h"}, "v - sin(h)")), {DomainRef::component(v, 1), h});
  cn.add(std::make_shared<CtcDeriv>(), {p, v});
  auto t = std::make_shared<Interval>(4.0, 4.1);
  // True path: p(t) = (4 sin(t/4), 4 - 4 cos(t/4)).
  auto z = std::make_shared<IntervalVector>(IntervalVector{{4 * std::sin(1.0) - 0.1, 4 * std::sin(1.0) + 0.1},
                                                           {4 - 4 * std::cos(1.0) - 0.1, 4 - 4 * std::cos(1.0) + 0.1}});
  cn.add(std::make_shared<CtcEval>(), {t, z, p, v});
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_TRUE(p->contains({Trajectory("4*sin(t/4)", td->t0_tf()), Trajectory("4 - 4*cos(t/4)", td->t0_tf())}));
  EXPECT_LT((*p)[0].gate(0).diam(), 0.5);
}

TEST(TubeNodes, ArgumentErrorsLeaveTheNetworkUnchanged) {
  auto td = TDomain::create(0.0, 1.0, 0.1), other = TDomain::create(0.0, 1.0, 0.2);
  auto x = std::make_shared<Tube>(td), v = std::make_shared<Tube>(other);
  auto a = std::make_shared<Interval>(0, 1);
  ContractorNetwork cn;
  EXPECT_THROW(cn.add(std::make_shared<CtcDeriv>(), {x}), DimensionError);
  EXPECT_THROW(cn.add(std::make_shared<CtcDeriv>(), {x, v}), DimensionError);
  EXPECT_THROW(cn.add(std::make_shared<CtcDeriv>(), {x, a}), DimensionError);
  EXPECT_THROW(cn.add(std::make_shared<CtcEval>(), {x, a, x}), DimensionError);
  EXPECT_THROW(cn.add(std::make_shared<CtcEval>(), {a, a}), DimensionError);
  EXPECT_EQ(cn.nb_dom(), 0u);
  EXPECT_EQ(cn.nb_ctc(), 0u);
}

TEST(TubeNodes, IncrementsContractTheGatesOnly) {
  auto td = TDomain::create(0.0, 4.0, 1.0);
  Tube x(td), i(td, Interval(1.0, 1.5));
  x.set_gate(0, Interval(0.0));
  x.set_gate(4, Interval(4.0, 5.0));
  ASSERT_TRUE(CtcIncrement().contract(x, i));
  EXPECT_EQ(x.gate(1), Interval(1.0, 1.5));
  EXPECT_EQ(x.gate(2), Interval(2.0, 3.0));
  EXPECT_EQ(x.gate(3), Interval(3.0, 4.0));  // backward from [4, 5]: [2.5, 4]
  EXPECT_EQ(x.gate(4), Interval(4.0, 5.0));
  EXPECT_EQ(x.slice(1), Interval());  // slices are CtcDeriv's business
  // In a network, with the same result; inconsistency empties.
  auto nx = std::make_shared<Tube>(td), ni = std::make_shared<Tube>(i);
  nx->set_gate(0, Interval(0.0));
  nx->set_gate(4, Interval(4.0, 5.0));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcIncrement>(), {nx, ni});
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ(*nx, x);
  Tube y(td);
  y.set_gate(0, Interval(0.0));
  y.set_gate(4, Interval(10.0));
  EXPECT_FALSE(CtcIncrement().contract(y, i));
  EXPECT_TRUE(y.is_empty());
}

// A CtcEval node leaves its fronts beyond [t] to the network's CtcDeriv on
// the same (y, w) (both sweeps): the fixed point of the network is the one of
// the standalone call (which runs CtcDeriv itself). Without such a CtcDeriv,
// or with a one-way one, the node sweeps its fronts both ways itself.
TEST(TubeNodes, EvalLeavesItsFrontsToTheNetworksDeriv) {
  auto td = TDomain::create(0.0, 6.0, 0.05);
  const Tube v(td, "cos(t) + [-0.05, 0.05]");
  const Interval t0(2.95, 3.05), z0(std::sin(3.0) - 1e-3, std::sin(3.0) + 1e-3);
  Tube direct(td);
  Interval td_t = t0, td_z = z0;
  ASSERT_TRUE(CtcEval().contract(td_t, td_z, direct, v));
  const auto solve = [&](std::shared_ptr<const CtcDeriv> deriv, Interval& t, Interval& z) {
    auto x = std::make_shared<Tube>(td);
    auto nv = std::make_shared<Tube>(v);
    auto nt = std::make_shared<Interval>(t0), nz = std::make_shared<Interval>(z0);
    ContractorNetwork cn;
    cn.set_ratio(0.0);
    if (deriv) cn.add(deriv, {x, nv});
    cn.add(std::make_shared<CtcEval>(), {nt, nz, x, nv});
    EXPECT_FALSE(cn.contract().empty);
    t = *nt;
    z = *nz;
    return *x;
  };
  Interval t, z;
  const Tube with_deriv = solve(std::make_shared<CtcDeriv>(), t, z);
  EXPECT_EQ(with_deriv, direct);
  EXPECT_EQ(t, td_t);
  EXPECT_EQ(z, td_z);
  for (const auto& deriv : {std::shared_ptr<const CtcDeriv>(), std::make_shared<const CtcDeriv>(TimePropag::FORWARD)}) {
    const Tube x = solve(deriv, t, z);
    EXPECT_TRUE(x.contains(Trajectory("sin(t)", td->t0_tf())));
    EXPECT_LT(x.gate(0).diam(), 1.0);  // the backward front reached t0
    EXPECT_LT(x.gate(td->nb_slices()).diam(), 1.0);
    EXPECT_TRUE(direct.is_subset(x));
  }
}

// The node itself: told that the network runs CtcDeriv on (x, v), one run
// changes only the slices around [t]; not told, its fronts go on beyond.
TEST(TubeNodes, EvalNodeSweepsBeyondOnlyWithoutTheNetworksDeriv) {
  auto td = TDomain::create(0.0, 6.0, 0.05);  // 120 slices, 241 atoms
  const auto run_once = [&](bool told) {
    auto x = std::make_shared<Tube>(td, Interval(-10, 10));
    x->set_gate(0, Interval(0.0));
    auto nt = std::make_shared<IntervalDomain>(std::make_shared<Interval>(2.95, 3.05));
    auto nz = std::make_shared<IntervalDomain>(std::make_shared<Interval>(std::sin(3.0) - 1e-3, std::sin(3.0) + 1e-3));
    auto nx = std::make_shared<TubeDomain>(x);
    auto nv = std::make_shared<TubeDomain>(std::make_shared<Tube>(td, "cos(t) + [-0.05, 0.05]"));
    const std::vector<BoundDomain> args{{nt, {0, 0, 1}}, {nz, {1, 0, 1}}, {nx, {2, 0, 241}}, {nv, {3, 0, 241}}};
    const auto node = CtcEval().make_node(args);
    const std::vector<std::shared_ptr<Domain>> domains{nt, nz, nx, nv};
    const std::vector<DerivativePair> pairs{{args[2].range, args[3].range}};
    std::vector<std::size_t> changed;
    NodeRun run{domains, 0.01, true, {}, changed};
    if (told) run.derivatives = pairs;
    EXPECT_TRUE(run.has_derivative(args[2].range, args[3].range) == told);
    EXPECT_TRUE(node->run(run));
    // One pass; it shrank the region, so the node asks the network to run it again.
    EXPECT_FALSE(run.changed.empty());
    EXPECT_TRUE(run.again);
    return *x;
  };
  const Tube left = run_once(true), swept = run_once(false);
  EXPECT_EQ(left.gate(100), Interval(-10, 10));  // t = 5: beyond [t], untouched
  EXPECT_LT(swept.gate(100).diam(), 1.0);         // the forward front reached it
  EXPECT_TRUE(swept.is_subset(left));
  EXPECT_EQ(left.gate(60), swept.gate(60));  // t = 3: the region is the same
}

// Which nodes say they enforce x' = v: CtcDeriv with both sweeps, per component pair.
TEST(TubeNodes, DerivativePairsOfTheNodes) {
  auto td = TDomain::create(0.0, 1.0, 0.1);  // 21 atoms per tube
  std::vector<BoundDomain> args;
  for (std::size_t i = 0; i < 4; ++i) args.push_back({std::make_shared<TubeDomain>(std::make_shared<Tube>(td)), {i, 0, 21}});
  std::vector<DerivativePair> pairs;
  CtcDeriv().make_node(args)->derivative_pairs(pairs);  // x = (args 0, 1), v = (args 2, 3)
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].x.domain, 0u);
  EXPECT_EQ(pairs[0].v.domain, 2u);
  EXPECT_EQ(pairs[1].x.domain, 1u);
  EXPECT_EQ(pairs[1].v.domain, 3u);
  pairs.clear();
  CtcDeriv(TimePropag::FORWARD).make_node(args)->derivative_pairs(pairs);
  CtcDeriv(TimePropag::BACKWARD).make_node(args)->derivative_pairs(pairs);
  CtcIncrement().make_node({args[0], args[2]})->derivative_pairs(pairs);
  EXPECT_TRUE(pairs.empty());
}
