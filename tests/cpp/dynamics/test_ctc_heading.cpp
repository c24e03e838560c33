// CtcHeading: p(t_{k+1}) − p(t_k) ∈ d_k (cos, sin)(ψ over the slice ± track),
// both ways. The contractor laws on a vehicle turning at a constant rate
// (exact trajectory), exact one-slice cases (forward, backward, across ±π,
// inconsistency), the network form and argument errors.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "sillage/testing/contractor_kit.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/error.h"
#include "sillage/interval/elementary.h"
#include "turning_vehicle.h"

using namespace sillage;

namespace {

using test::Turning;

constexpr double kTrack = 0.05;

// Domains: p (2-d), psi, d (slices: distance per slice), w (ψ').
kit::Case heading_case(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Turning f{3 * u(rng), 0.5 + 0.4 * u(rng), 1.5 + u(rng), kTrack * u(rng), 5 * u(rng), 5 * u(rng)};
  const auto td = kit::random_tdomain(rng, 25);
  const std::size_t n = td->nb_slices();
  std::vector<Interval> dist(n);
  for (std::size_t k = 0; k < n; ++k) dist[k] = kit::around(Interval(f.s) * td->slice_width(k), rng, 0.05);
  const kit::Trajectory1 px = [f](const Interval& t) { return f.x(t); };
  const kit::Trajectory1 py = [f](const Interval& t) { return f.y(t); };
  const kit::Trajectory1 psi = [f](const Interval& t) { return f.psi(t); };
  kit::Case c;
  TubeVector p({kit::tube_around(td, px, rng, 2.0, 0.3), kit::tube_around(td, py, rng, 2.0, 0.3)});
  p.set_gate(0, IntervalVector{kit::around(f.x(Interval(0.0)), rng, 0.05), kit::around(f.y(Interval(0.0)), rng, 0.05)});
  c.domains = {p, kit::tube_around(td, psi, rng, 1.5, 0.3), Tube(td, dist, std::vector<Interval>(n + 1, Interval())),
               Tube(td, kit::around(Interval(f.b), rng, 0.2))};
  c.truth = {std::vector<kit::Trajectory1>{px, py}, psi, std::monostate{}, std::monostate{}};
  return c;
}

void heading_contract(kit::Domains& d) {
  CtcHeading(kTrack).contract(std::get<TubeVector>(d[0]), std::get<Tube>(d[1]), std::get<Tube>(d[2]),
                              std::get<Tube>(d[3]));
}

// One slice of width 1 on [0, 1].
std::shared_ptr<TDomain> one_slice() { return TDomain::create(std::vector<double>{0.0, 1.0}); }

}  // namespace

TEST(CtcHeading, ContractorLaws) {
  kit::Options o;
  o.outputs = {0, 1};
  o.idempotence = kit::Idempotence::ContractionOnly;  // the heading and the positions feed each other
  EXPECT_TRUE(kit::check_laws(heading_contract, heading_case, o));
}

TEST(CtcHeading, LawsInANetworkWithTheHeadingIncrements) {
  // The network form: CtcHeading with CtcDeriv on psi; the truth stays inside.
  const auto contract = [](kit::Domains& d) {
    auto p = std::make_shared<TubeVector>(std::get<TubeVector>(d[0]));
    auto psi = std::make_shared<Tube>(std::get<Tube>(d[1]));
    auto dist = std::make_shared<Tube>(std::get<Tube>(d[2]));
    auto w = std::make_shared<Tube>(std::get<Tube>(d[3]));
    ContractorNetwork cn;
    cn.add(std::make_shared<CtcHeading>(kTrack), {p, psi, dist, w});
    cn.add(std::make_shared<CtcDeriv>(), {psi, w});
    cn.contract();
    d[0] = *p, d[1] = *psi;
  };
  kit::Options o;
  o.cases = 20;
  o.outputs = {0, 1};
  o.empty_any = true;
  o.threads = false;  // a network per call: law (e) is the direct call's
  o.idempotence = kit::Idempotence::ContractionOnly;
  EXPECT_TRUE(kit::check_laws(contract, heading_case, o));
}

TEST(CtcHeading, ForwardOneSliceIsTheRotatedDistance) {
  const auto td = one_slice();
  TubeVector p(td, 2);
  p.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
  Tube psi(td, Interval(0.0)), d(td, Interval(2.0)), w(td, Interval(0.0));
  ASSERT_TRUE(CtcHeading().contract(p, psi, d, w));
  EXPECT_TRUE(p[0].gate(1).contains(2.0));
  EXPECT_LT(p[0].gate(1).diam(), 1e-12);
  EXPECT_TRUE(p[1].gate(1).contains(0.0));
  EXPECT_LT(p[1].gate(1).diam(), 1e-12);
  // With the track error: the direction lies in [-0.1, 0.1], the increment in 2 (cos, sin) of it.
  TubeVector q(td, 2);
  q.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
  ASSERT_TRUE(CtcHeading(0.1).contract(q, psi, d, w));
  EXPECT_NEAR(q[0].gate(1).lb(), 2 * std::cos(0.1), 1e-12);
  EXPECT_NEAR(q[0].gate(1).ub(), 2.0, 1e-12);
  EXPECT_NEAR(q[1].gate(1).lb(), -2 * std::sin(0.1), 1e-12);
  EXPECT_NEAR(q[1].gate(1).ub(), 2 * std::sin(0.1), 1e-12);
}

TEST(CtcHeading, BackwardOneSliceGivesTheHeadingFromTheDisplacement) {
  // Displacement in [0.9, 1.1]^2, turn rate within ±0.1 rad/s over 1 s: the heading lies
  // in [atan2(0.9, 1.1) - 0.1, atan2(1.1, 0.9) + 0.1], its gates too.
  const auto td = one_slice();
  TubeVector p(td, 2);
  p.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
  p.set_gate(1, IntervalVector{Interval(0.9, 1.1), Interval(0.9, 1.1)});
  Tube psi(td, Interval(-1.0, 2.0)), d(td, Interval(0.0, 10.0)), w(td, Interval(-0.1, 0.1));
  ASSERT_TRUE(CtcHeading().contract(p, psi, d, w));
  const double lo = std::atan2(0.9, 1.1) - 0.1, hi = std::atan2(1.1, 0.9) + 0.1;
  for (const Interval& h : {psi.slice(0), psi.gate(0), psi.gate(1)}) {
    EXPECT_TRUE(h.contains(lo) && h.contains(hi)) << h;
    EXPECT_LT(h.diam(), hi - lo + 1e-9) << h;
  }
  // The same 2π further on: the heading is an unwrapped angle.
  Tube psi2(td, Interval(5.0, 8.0));
  ASSERT_TRUE(CtcHeading().contract(p, psi2, d, w));
  EXPECT_TRUE(psi2.slice(0).contains(lo + 2 * M_PI) && psi2.slice(0).contains(hi + 2 * M_PI));
  EXPECT_LT(psi2.slice(0).diam(), hi - lo + 1e-9);
}

TEST(CtcHeading, BackwardAcrossMinusPi) {
  // Displacement towards -x: direction ±atan(0.1/0.9) around π, read from the range [-4, 0]
  // as around -π (atan2 would cut there).
  const auto td = one_slice();
  TubeVector p(td, 2);
  p.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
  p.set_gate(1, IntervalVector{Interval(-1.1, -0.9), Interval(-0.1, 0.1)});
  Tube psi(td, Interval(-4.0, 0.0)), d(td, Interval(0.0, 10.0)), w(td, Interval(0.0));
  ASSERT_TRUE(CtcHeading().contract(p, psi, d, w));
  const double half = std::atan2(0.1, 0.9);
  EXPECT_TRUE(psi.slice(0).contains(-M_PI - half) && psi.slice(0).contains(-M_PI + half)) << psi.slice(0);
  EXPECT_LT(psi.slice(0).diam(), 2 * half + 1e-9);
}

TEST(CtcHeading, NothingLearnedWhenTheDirectionsMaySpanAHalfTurn) {
  // A turn rate of 4 rad/s over 1 s: the heading may sweep more than π, so the displacement
  // says nothing about it.
  const auto td = one_slice();
  TubeVector p(td, 2);
  p.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
  p.set_gate(1, IntervalVector{Interval(1.0), Interval(0.0)});
  Tube psi(td, Interval(-1.0, 2.0)), d(td, Interval(0.0, 10.0)), w(td, Interval(-4.0, 4.0));
  ASSERT_TRUE(CtcHeading().contract(p, psi, d, w));
  EXPECT_EQ(psi.slice(0), Interval(-1.0, 2.0));
}

TEST(CtcHeading, InconsistentDisplacementIsEmpty) {
  // Heading in [0, 0.1], 1 m travelled, but the end is 2 m behind: no trajectory.
  const auto td = one_slice();
  TubeVector p(td, 2);
  p.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
  p.set_gate(1, IntervalVector{Interval(-2.0, -1.5), Interval(-0.5, 0.5)});
  Tube psi(td, Interval(0.0, 0.1)), d(td, Interval(1.0)), w(td, Interval(0.0));
  EXPECT_FALSE(CtcHeading().contract(p, psi, d, w));
  EXPECT_TRUE(p.is_empty());
  EXPECT_TRUE(psi.is_empty());
}

TEST(CtcHeading, InTheNetworkEmptinessNamesIt) {
  const auto td = one_slice();
  auto p = std::make_shared<TubeVector>(td, 2);
  p->set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
  p->set_gate(1, IntervalVector{Interval(-2.0, -1.5), Interval(-0.5, 0.5)});
  auto psi = std::make_shared<Tube>(td, Interval(0.0, 0.1));
  auto d = std::make_shared<Tube>(td, Interval(1.0));
  auto w = std::make_shared<Tube>(td, Interval(0.0));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcHeading>(), {p, psi, d, w});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_NE(s.emptiness.find("CtcHeading"), std::string::npos) << s.emptiness;
}

TEST(CtcHeading, NetworkEqualsTheDirectCall) {
  std::mt19937_64 rng(7);
  const kit::Case c = heading_case(rng);
  TubeVector p = std::get<TubeVector>(c.domains[0]);
  Tube psi = std::get<Tube>(c.domains[1]);
  const Tube& d = std::get<Tube>(c.domains[2]);
  const Tube& w = std::get<Tube>(c.domains[3]);
  auto np = std::make_shared<TubeVector>(p);
  auto npsi = std::make_shared<Tube>(psi);
  CtcHeading(kTrack).contract(p, psi, d, w);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcHeading>(kTrack), {np, npsi, std::make_shared<Tube>(d), std::make_shared<Tube>(w)});
  EXPECT_FALSE(cn.contract().empty);
  // The network runs the node to its own fixed point: at least as narrow as one call.
  EXPECT_TRUE(np->is_subset(p));
  EXPECT_TRUE(npsi->is_subset(psi));
}

TEST(CtcHeading, ArgumentErrors) {
  EXPECT_THROW(CtcHeading(-0.1), Error);
  EXPECT_THROW(CtcHeading(NAN), Error);
  const auto td = one_slice();
  TubeVector p3(td, 3);
  Tube psi(td), d(td), w(td);
  EXPECT_THROW(CtcHeading().contract(p3, psi, d, w), DimensionError);
  const auto other = TDomain::create(std::vector<double>{0.0, 2.0});
  Tube w2(other);
  TubeVector p(td, 2);
  EXPECT_THROW(CtcHeading().contract(p, psi, d, w2), DimensionError);
  ContractorNetwork cn;
  EXPECT_THROW(cn.add(std::make_shared<CtcHeading>(), {std::make_shared<TubeVector>(td, 2), std::make_shared<Tube>(td)}),
               DimensionError);
}
