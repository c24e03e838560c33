// CtcHeadingWindow: p(t_b) − p(t_a) ∈ Rot(ψ(t_c)) Σ_j d_j (cos, sin)(R_j ± track)
// over windows of slices, both ways. The contractor laws on a vehicle turning
// at a constant rate (exact trajectory; alone and in a network with the
// increments and the turn rate), exact straight-line windows (heading from the
// positions, across 2π, positions from the heading), the turn inside a slice,
// inconsistency (named by the network) and argument errors.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "sillage/testing/contractor_kit.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/error.h"
#include "sillage/interval/elementary.h"
#include "sillage/interval/arith_rows.h"
#include "turning_vehicle.h"

using namespace sillage;

namespace {

using test::Turning;

constexpr double kTrack = 0.05, kWindow = 2.0, kAccel = 1.0;

// Domains: p (2-d), psi, d (slices: distance), dpsi (slices: heading increments), w (ψ').
kit::Case window_case(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Turning f{3 * u(rng), 0.5 + 0.4 * u(rng), 1.5 + u(rng), kTrack * u(rng), 5 * u(rng), 5 * u(rng)};
  const auto td = kit::random_tdomain(rng, 25);
  const std::size_t n = td->nb_slices();
  std::vector<Interval> dist(n), dpsi(n);
  for (std::size_t k = 0; k < n; ++k) {
    dist[k] = kit::around(Interval(f.s) * td->slice_width(k), rng, 0.05);
    dpsi[k] = kit::around(Interval(f.b) * td->slice_width(k), rng, 0.02);
  }
  const std::vector<Interval> free(n + 1, Interval());
  const kit::Trajectory1 px = [f](const Interval& t) { return f.x(t); };
  const kit::Trajectory1 py = [f](const Interval& t) { return f.y(t); };
  const kit::Trajectory1 psi = [f](const Interval& t) { return f.psi(t); };
  kit::Case c;
  TubeVector p({kit::tube_around(td, px, rng, 2.0, 0.3), kit::tube_around(td, py, rng, 2.0, 0.3)});
  c.domains = {p, kit::tube_around(td, psi, rng, 1.5, 0.3), Tube(td, dist, free), Tube(td, dpsi, free),
               Tube(td, kit::around(Interval(f.b), rng, 0.2))};
  c.truth = {std::vector<kit::Trajectory1>{px, py}, psi, std::monostate{}, std::monostate{}, std::monostate{}};
  return c;
}

void window_contract(kit::Domains& d) {
  CtcHeadingWindow(kWindow, kTrack, kAccel).contract(std::get<TubeVector>(d[0]), std::get<Tube>(d[1]),
                                                     std::get<Tube>(d[2]), std::get<Tube>(d[3]), std::get<Tube>(d[4]));
}

// A straight run along +x at 1 m/s: ten slices of 1 s, d = 1 m, no turn.
struct Straight {
  std::shared_ptr<TDomain> td = TDomain::create(0.0, 10.0, 1.0);
  TubeVector p{td, 2};
  Tube psi{td}, d{td, Interval(1.0)}, dpsi{td, Interval(0.0)}, w{td, Interval(0.0)};
  Straight() { p.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)}); }
};

}  // namespace

TEST(CtcHeadingWindow, ContractorLaws) {
  kit::Options o;
  o.outputs = {0, 1};
  o.idempotence = kit::Idempotence::ContractionOnly;  // the heading and the positions feed each other
  EXPECT_TRUE(kit::check_laws(window_contract, window_case, o));
}

TEST(CtcHeadingWindow, LawsInANetworkWithTheIncrementsAndTheTurnRate) {
  // The plaza1 form: with CtcIncrement and CtcDeriv on psi; the truth stays inside.
  const auto contract = [](kit::Domains& d) {
    auto p = std::make_shared<TubeVector>(std::get<TubeVector>(d[0]));
    auto psi = std::make_shared<Tube>(std::get<Tube>(d[1]));
    auto dist = std::make_shared<Tube>(std::get<Tube>(d[2]));
    auto dpsi = std::make_shared<Tube>(std::get<Tube>(d[3]));
    auto w = std::make_shared<Tube>(std::get<Tube>(d[4]));
    ContractorNetwork cn;
    cn.add(std::make_shared<CtcHeadingWindow>(kWindow, kTrack, kAccel, 2), {p, psi, dist, dpsi, w});
    cn.add(std::make_shared<CtcIncrement>(), {psi, dpsi});
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
  EXPECT_TRUE(kit::check_laws(contract, window_case, o));
}

TEST(CtcHeadingWindow, HeadingFromAStraightWindow) {
  // 10 m along the heading ψ(t_5) (no turn, no track error): with p(t_10) in [9, 11] x [-1, 1],
  // ψ(t_5) lies within asin(0.1) of 0 (10 (cos, sin) ψ must meet the box), widened by at most
  // one cell (0.01 rad) and within the directions of the box, ±atan(1/9).
  Straight s;
  s.psi.set_gate(5, Interval(-3.0, 3.0));
  s.p.set_gate(10, IntervalVector{Interval(9.0, 11.0), Interval(-1.0, 1.0)});
  ASSERT_TRUE(CtcHeadingWindow(10.0).contract(s.p, s.psi, s.d, s.dpsi, s.w));
  const Interval h = s.psi.gate(5);
  EXPECT_TRUE(h.contains(-std::asin(0.1)) && h.contains(std::asin(0.1))) << h;
  EXPECT_LE(h.ub(), std::atan2(1.0, 9.0) + 1e-12) << h;
  EXPECT_GE(h.lb(), -std::atan2(1.0, 9.0) - 1e-12) << h;
  // The other gates are left to the increments (CtcIncrement in a network).
  EXPECT_TRUE(s.psi.gate(0).is_all_reals());
}

TEST(CtcHeadingWindow, HeadingIsAnUnwrappedAngle) {
  // The same two turns further on: the meet is taken modulo 2π.
  Straight s;
  s.psi.set_gate(5, Interval(4 * M_PI - 1.0, 4 * M_PI + 1.0));
  s.p.set_gate(10, IntervalVector{Interval(9.0, 11.0), Interval(-1.0, 1.0)});
  ASSERT_TRUE(CtcHeadingWindow(10.0).contract(s.p, s.psi, s.d, s.dpsi, s.w));
  EXPECT_TRUE(s.psi.gate(5).contains(4 * M_PI + 0.1) && s.psi.gate(5).contains(4 * M_PI - 0.1)) << s.psi.gate(5);
  EXPECT_LT(s.psi.gate(5).diam(), 2 * std::atan2(1.0, 9.0) + 1e-9);
}

TEST(CtcHeadingWindow, PositionsFromAKnownHeading) {
  // ψ(t_5) = π/2 exactly: p(t_10) = p(t_0) + 10 (0, 1), up to the rounding of cos and sin.
  Straight s;
  s.psi.set_gate(5, Interval::half_pi());
  ASSERT_TRUE(CtcHeadingWindow(10.0).contract(s.p, s.psi, s.d, s.dpsi, s.w));
  EXPECT_TRUE(s.p[0].gate(10).contains(0.0));
  EXPECT_TRUE(s.p[1].gate(10).contains(10.0));
  EXPECT_LT(s.p.gate(10).max_diam(), 1e-12);
  // And backwards: the end known, the start follows.
  Straight r;
  r.p.set_gate(0, IntervalVector(2));
  r.p.set_gate(10, IntervalVector{Interval(3.0), Interval(4.0)});
  r.psi.set_gate(5, Interval(0.0));
  ASSERT_TRUE(CtcHeadingWindow(10.0).contract(r.p, r.psi, r.d, r.dpsi, r.w));
  EXPECT_TRUE(r.p[0].gate(0).contains(-7.0) && r.p[1].gate(0).contains(4.0));
  EXPECT_LT(r.p.gate(0).max_diam(), 1e-12);
}

TEST(CtcHeadingWindow, TurnInsideASliceWidensTheWindow) {
  // One slice of 1 s, no net turn, |ψ'| <= 1 rad/s: ψ may leave 0 by up to ω δ / 2 = 0.5 rad
  // inside it, so the end lies in 1 (cos, sin)([-0.5, 0.5]). With |ψ''| <= 0.8 rad/s² it lies
  // within α δ² / 8 = 0.1 rad of the chord instead.
  const auto one = [](double accel) {
    const auto td = TDomain::create(std::vector<double>{0.0, 1.0});
    TubeVector p(td, 2);
    p.set_gate(0, IntervalVector{Interval(0.0), Interval(0.0)});
    Tube psi(td), d(td, Interval(1.0)), dpsi(td, Interval(0.0)), w(td, Interval(-1.0, 1.0));
    psi.set_gate(0, Interval(0.0));  // the middle gate of a one-slice window is its first
    EXPECT_TRUE(CtcHeadingWindow(1.0, 0.0, accel).contract(p, psi, d, dpsi, w));
    return p.gate(1);
  };
  const IntervalVector rate = one(INFINITY), accel = one(0.8);
  EXPECT_NEAR(rate[1].ub(), std::sin(0.5), 1e-9);
  EXPECT_NEAR(rate[0].lb(), std::cos(0.5), 1e-9);
  EXPECT_NEAR(accel[1].ub(), std::sin(0.1), 1e-9);
  EXPECT_NEAR(accel[0].lb(), std::cos(0.1), 1e-9);
}

TEST(CtcHeadingWindow, InconsistentDisplacementIsEmpty) {
  // Heading 0, 10 m travelled along it, but the end is behind the start.
  Straight s;
  s.psi.set_gate(5, Interval(-0.1, 0.1));
  s.p.set_gate(10, IntervalVector{Interval(-2.0, -1.0), Interval(-0.5, 0.5)});
  EXPECT_FALSE(CtcHeadingWindow(10.0).contract(s.p, s.psi, s.d, s.dpsi, s.w));
  EXPECT_TRUE(s.p.is_empty());
  EXPECT_TRUE(s.psi.is_empty());
}

TEST(CtcHeadingWindow, InTheNetworkEmptinessNamesIt) {
  Straight s;
  s.psi.set_gate(5, Interval(-0.1, 0.1));
  s.p.set_gate(10, IntervalVector{Interval(-2.0, -1.0), Interval(-0.5, 0.5)});
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcHeadingWindow>(10.0),
         {std::make_shared<TubeVector>(s.p), std::make_shared<Tube>(s.psi), std::make_shared<Tube>(s.d),
          std::make_shared<Tube>(s.dpsi), std::make_shared<Tube>(s.w)});
  const ContractStats st = cn.contract();
  EXPECT_TRUE(st.empty);
  EXPECT_NE(st.emptiness.find("CtcHeadingWindow"), std::string::npos) << st.emptiness;
}

TEST(CtcHeadingWindow, NetworkEqualsTheDirectCall) {
  std::mt19937_64 rng(11);
  const kit::Case c = window_case(rng);
  TubeVector p = std::get<TubeVector>(c.domains[0]);
  Tube psi = std::get<Tube>(c.domains[1]);
  const Tube &d = std::get<Tube>(c.domains[2]), &dpsi = std::get<Tube>(c.domains[3]), &w = std::get<Tube>(c.domains[4]);
  auto np = std::make_shared<TubeVector>(p);
  auto npsi = std::make_shared<Tube>(psi);
  const CtcHeadingWindow ctc(kWindow, kTrack, kAccel);
  ctc.contract(p, psi, d, dpsi, w);
  // The case is not vacuous: the windows contract the positions.
  EXPECT_FALSE(std::get<TubeVector>(c.domains[0]).is_subset(p));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcHeadingWindow>(ctc),
         {np, npsi, std::make_shared<Tube>(d), std::make_shared<Tube>(dpsi), std::make_shared<Tube>(w)});
  EXPECT_FALSE(cn.contract().empty);
  // The network's first run is the direct call; later runs only contract.
  EXPECT_TRUE(np->is_subset(p));
  EXPECT_TRUE(npsi->is_subset(psi));
}

TEST(CtcHeadingWindow, RandomCasesContractTheHeading) {
  // The laws' cases are not vacuous: in some of them the positions give the heading.
  std::mt19937_64 rng(5);
  int narrowed = 0;
  for (int i = 0; i < 20; ++i) {
    kit::Case c = window_case(rng);
    const Tube before = std::get<Tube>(c.domains[1]);
    window_contract(c.domains);
    narrowed += !before.is_subset(std::get<Tube>(c.domains[1]));
  }
  EXPECT_GT(narrowed, 0);
}

TEST(CtcHeadingWindow, RowsAndOneAtATimeGiveTheSameBits) {
  // The cells' turns of V and the window sums go through the AVX2 rows where they run: the
  // operators' bits, so the same tubes as one interval at a time.
  std::mt19937_64 rng(17);
  for (int i = 0; i < 20; ++i) {
    const kit::Case c = window_case(rng);
    kit::Domains rows = c.domains, single = c.domains;
    window_contract(rows);
    detail::set_avx2_rows(false);
    window_contract(single);
    detail::set_avx2_rows(true);
    for (std::size_t k = 0; k < 2; ++k) {
      const Tube &a = k == 0 ? std::get<Tube>(rows[1]) : std::get<TubeVector>(rows[0])[0];
      const Tube &b = k == 0 ? std::get<Tube>(single[1]) : std::get<TubeVector>(single[0])[0];
      ASSERT_EQ(a.data().gates, b.data().gates) << i;
      ASSERT_EQ(a.data().slices, b.data().slices) << i;
    }
  }
}

TEST(CtcHeadingWindow, ArgumentErrors) {
  EXPECT_THROW((CtcHeadingWindow{0.0}), Error);
  EXPECT_THROW((CtcHeadingWindow{INFINITY}), Error);
  EXPECT_THROW((CtcHeadingWindow{1.0, -0.1}), Error);
  EXPECT_THROW((CtcHeadingWindow{1.0, 0.0, 0.0}), Error);
  EXPECT_THROW((CtcHeadingWindow{1.0, 0.0, NAN}), Error);
  EXPECT_THROW((CtcHeadingWindow{1.0, 0.0, INFINITY, 0}), Error);
  const auto td = TDomain::create(0.0, 2.0, 1.0);
  TubeVector p3(td, 3);
  Tube psi(td), d(td), dpsi(td), w(td);
  EXPECT_THROW(CtcHeadingWindow(1.0).contract(p3, psi, d, dpsi, w), DimensionError);
  const auto other = TDomain::create(0.0, 2.0, 0.5);
  TubeVector p(td, 2);
  Tube w2(other);
  EXPECT_THROW(CtcHeadingWindow(1.0).contract(p, psi, d, dpsi, w2), DimensionError);
  ContractorNetwork cn;
  EXPECT_THROW(cn.add(std::make_shared<CtcHeadingWindow>(1.0), {std::make_shared<TubeVector>(td, 2), std::make_shared<Tube>(td)}),
               DimensionError);
}

// Windows start every `stride` slices counted from the TDomain's first day:
// a domain that forgot its past (online) keeps the windows of the whole
// mission, so that the online and batch solves apply the same constraints.
TEST(CtcHeadingWindow, WindowsKeepTheirPlaceWhenThePastIsForgotten) {
  auto td = TDomain::create(0.0, 12.0, 1.0);
  TubeVector p(td, 2);
  Tube psi(td, Interval(-0.01, 0.01)), d(td, Interval(1.0)), dpsi(td, Interval(0.0)), w(td, Interval(-0.1, 0.1));
  ASSERT_EQ(td->forget_before(1.0), 1u);  // slice [0, 1] gone: slice k is slice k + 1 of the first day
  p.set_gate(3, IntervalVector{Interval(0.0), Interval(0.0)});  // p(4) = 0
  // Windows of 2 s every 4 slices: [4, 6], [8, 10] (not [1, 3], [5, 7], [9, 11]).
  ASSERT_TRUE(CtcHeadingWindow(2.0, 0.0, INFINITY, 4).contract(p, psi, d, dpsi, w));
  EXPECT_TRUE(p[0].gate(5).is_bounded()) << p[0].gate(5);  // p(6) from p(4)
  EXPECT_TRUE(p[0].gate(5).contains(2.0)) << p[0].gate(5);
  EXPECT_FALSE(p[0].gate(6).is_bounded()) << p[0].gate(6);  // p(7): no window ends there
}
