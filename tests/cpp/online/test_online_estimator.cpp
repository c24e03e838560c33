// OnlineEstimator: the truth inside every estimate at every time, the batch
// solve inside the online one, W = ∞ ending at the batch fixed point, arrival
// orders that agree, a window that forgets without losing the truth, and the
// errors on bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "online/online_scenario.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/error.h"

using namespace sillage;
using sillage::test::Scenario;

namespace {

// The truth inside the tube at every slice and gate, and inside [p](t) at
// times sampled between the gates.
void expect_truth_inside(const TubeVector& p, const char* when) {
  const TDomain& td = *p.tdomain();
  for (std::size_t k = 0; k < td.nb_slices(); ++k) {
    const Interval tk = td.slice_domain(k);
    ASSERT_TRUE(p.gate(k).contains(test::truth(Interval(td.t(k))).mid())) << when << " gate " << k;
    for (int i = 1; i < 4; ++i) {
      const double t = tk.lb() + i * 0.25 * tk.diam();
      const Vector x = test::truth(Interval(t)).mid();
      ASSERT_TRUE(p(t).contains(x)) << when << " at t = " << t;
    }
  }
}

// The batch solve of the same data: every period and range known at once.
std::shared_ptr<TubeVector> batch(const Scenario& s, double ratio) {
  std::vector<double> times;
  for (std::size_t k = 0; k <= s.steps; ++k) times.push_back(s.time(k));
  auto td = TDomain::create(times);
  auto p = std::make_shared<TubeVector>(td, 2);
  auto v = std::make_shared<TubeVector>(td, 2);
  p->set_gate(0, s.start());
  for (std::size_t k = 1; k <= s.steps; ++k) {
    for (std::size_t i = 0; i < 2; ++i) (*v)[i].write().slices()[k - 1] = s.input(k)[i];
  }
  ContractorNetwork cn;
  cn.set_ratio(ratio);
  cn.add(std::make_shared<CtcDeriv>(), {p, v});
  for (const auto& r : s.ranges) {
    auto q = std::make_shared<IntervalVector>(2);
    cn.add(Scenario::range_ctc(), {q, r.beacon, r.range});
    cn.add(std::make_shared<CtcEval>(), {std::make_shared<Interval>(r.t), q, p, v});
  }
  EXPECT_FALSE(cn.contract().empty);
  return p;
}

}  // namespace

TEST(OnlineEstimator, TheTruthStaysInsideAtEveryUpdate) {
  const Scenario s(1);
  auto est = s.estimator({});
  s.replay(*est, s.ranges, [&] {
    const IntervalVector now = est->now("p");
    ASSERT_TRUE(now.contains(test::truth(Interval(est->now())).mid())) << "t = " << est->now();
    ASSERT_EQ(est->last_update().summary.status, Status::Converged);
  });
  expect_truth_inside(*est->tube("p"), "end");
  EXPECT_EQ(est->stats().observations, s.ranges.size());
  EXPECT_EQ(est->stats().slices, s.steps);
}

TEST(OnlineEstimator, TheBatchSolveIsInsideTheOnlineEstimateAndEqualsItsFixedPoint) {
  // Ratio 0: both propagations go to their fixed points (with a ratio, one
  // may stop a little before the other: both enclosures, not comparable).
  const Scenario s(2);
  const auto b = batch(s, 0.0);
  OnlineOptions o;
  o.ratio = 0.0;
  auto est = s.estimator(o);
  s.replay(*est, s.ranges, [&] {
    const std::size_t k = est->tube("p")->nb_slices();
    ASSERT_TRUE(b->gate(k).is_subset(est->now("p")))
        << "t = " << est->now() << " batch " << b->gate(k) << " online " << est->now("p");  // online never knows more
  });
  const TubeVector& online = *est->tube("p");
  const auto inside = [&] {
    for (std::size_t k = 0; k < online.nb_slices(); ++k) {
      if (!b->slice(k).is_subset(online.slice(k)) || !b->gate(k).is_subset(online.gate(k))) return false;
    }
    return true;
  };
  EXPECT_TRUE(inside());
  // The filtering estimate at now is already the batch one at the last time.
  const std::size_t n = online.nb_slices();
  EXPECT_NEAR(online.gate(n)[0].diam(), b->gate(n)[0].diam(), 1e-9 + 0.01 * b->gate(n)[0].diam());
  est->network().contract();  // W = ∞ and all the data: the batch fixed point
  EXPECT_TRUE(inside());
  EXPECT_LE(online.volume(), b->volume() * (1 + 1e-6));
}

TEST(OnlineEstimator, TwoArrivalOrdersGiveTheSameDomains) {
  const Scenario s(3);
  std::vector<test::Range> shuffled = s.ranges;
  // Swap neighbours: each range arrives a bit later or earlier, within the window.
  for (std::size_t i = 0; i + 1 < shuffled.size(); i += 2) {
    std::swap(shuffled[i], shuffled[i + 1]);
    shuffled[i].arrival = shuffled[i + 1].arrival = std::max(shuffled[i].arrival, shuffled[i + 1].arrival);
  }
  OnlineOptions o;
  o.ratio = 0.0;
  auto a = s.estimator(o), b = s.estimator(o);
  s.replay(*a, s.ranges, [] {});
  s.replay(*b, shuffled, [] {});
  a->network().contract();
  b->network().contract();
  const TubeVector &pa = *a->tube("p"), &pb = *b->tube("p");
  for (std::size_t k = 0; k < pa.nb_slices(); ++k) {
    for (std::size_t i = 0; i < 2; ++i) {
      ASSERT_NEAR(pa[i].slice(k).lb(), pb[i].slice(k).lb(), 1e-9) << k;
      ASSERT_NEAR(pa[i].slice(k).ub(), pb[i].slice(k).ub(), 1e-9) << k;
    }
  }
}

TEST(OnlineEstimator, AWindowForgetsThePastWithoutLosingTheTruth) {
  const Scenario s(4, 1500);  // 300 s
  OnlineOptions o;
  o.window = 10.0;
  auto est = s.estimator(o);
  std::size_t most = 0;
  s.replay(*est, s.ranges, [&] {
    ASSERT_TRUE(est->now("p").contains(test::truth(Interval(est->now())).mid())) << "t = " << est->now();
    most = std::max(most, est->stats().slices);
    ASSERT_GE(est->window_start(), est->now() - 10.0 - 1.25 - 0.2 - 1e-9);
  });
  expect_truth_inside(*est->tube("p"), "window");
  const OnlineStats st = est->stats();
  EXPECT_LE(most, static_cast<std::size_t>((10.0 + 1.25) / 0.2) + 2);
  EXPECT_GT(st.forgotten, 1300u);
  EXPECT_GT(st.retired, 0u);
  EXPECT_LT(st.observations, 40u);
  EXPECT_EQ(st.updates, s.steps + s.ranges.size());
}

TEST(OnlineEstimator, BadInputIsRefusedWithNothingLost) {
  const Scenario s(5, 100);
  OnlineOptions o;
  o.window = 5.0;
  auto est = s.estimator(o);
  EXPECT_THROW(est->observe(Interval(0, 0.1), "p", Scenario::range_ctc(), {}), Error);  // no time yet
  for (std::size_t k = 1; k <= 60; ++k) est->advance(s.time(k), {{"v", s.input(k)}});
  const IntervalVector before = est->now("p");
  const auto r = s.ranges.front();
  auto obs = [&](const Interval& t) { return est->observe(t, "p", Scenario::range_ctc(), {r.beacon, r.range}); };
  EXPECT_THROW(obs(Interval(12.5, 13)), Error);                       // in the future of now = 12
  EXPECT_THROW(obs(Interval(0.1, 0.3)), Error);                        // older than the window
  EXPECT_THROW(obs(Interval::empty()), Error);
  EXPECT_THROW(est->observe(Interval(11, 11.5), "q", Scenario::range_ctc(), {r.beacon, r.range}), Error);
  EXPECT_THROW(est->observe(Interval(11, 11.5), "p", Scenario::range_ctc(), {r.beacon}), DimensionError);
  EXPECT_THROW(est->advance(12.0), Error);                             // not after now
  EXPECT_THROW(est->advance(std::nan("")), Error);
  EXPECT_THROW(est->advance(12.2, {{"w", s.input(61)}}), Error);      // unknown input
  EXPECT_THROW(est->advance(12.2, {{"p", s.input(61)}}), Error);      // a state, not an input
  EXPECT_THROW(est->advance(12.2, {{"v", IntervalVector(3)}}), DimensionError);
  EXPECT_THROW(est->advance(12.2, {{"v", IntervalVector{Interval::empty(), Interval(0, 1)}}}), Error);
  EXPECT_THROW(est->add_state("x", 1), Error);                         // the model is fixed
  EXPECT_EQ(est->now(), 12.0);
  EXPECT_EQ(est->now("p"), before);
  const auto& late = *std::find_if(s.ranges.begin(), s.ranges.end(), [](const auto& x) { return x.t.lb() > 8; });
  EXPECT_EQ(est->observe(late.t, "p", Scenario::range_ctc(), {late.beacon, late.range}), 0u);  // still works
  EXPECT_EQ(est->stats().observations, 1u);
  EXPECT_TRUE(est->now("p").contains(test::truth(Interval(12.0)).mid()));
  EXPECT_THROW(OnlineEstimator(std::nan(""), {}), Error);
  OnlineOptions bad;
  bad.window = -1;
  EXPECT_THROW(OnlineEstimator(0.0, bad), Error);
}
