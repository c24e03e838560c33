// Property tests of Tube evaluation (3.3) and inversion (3.4) against their
// definitions, on random tubes; concurrent copies attaching to one TDomain.
#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "sillage/error.h"
#include "sillage/tube/tube.h"

using namespace sillage;

namespace {

Tube random_tube(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> d(0.1, 1.0), c(-2.0, 2.0), r(0.0, 1.0);
  std::vector<double> ts{0.0};
  const int n = std::uniform_int_distribution<int>(1, 12)(rng);
  for (int i = 0; i < n; ++i) ts.push_back(ts.back() + d(rng));
  auto td = TDomain::create(ts);
  auto random_interval = [&]() {
    const double m = c(rng), w = r(rng);
    return Interval(m - w, m + w);
  };
  std::vector<Interval> slices;
  for (int i = 0; i < n; ++i) slices.push_back(random_interval());
  // Gates independent of the slices (set_gate does not check them, the constructor would).
  Tube x(td, slices);
  for (int i = 0; i <= n; ++i) x.set_gate(static_cast<std::size_t>(i), random_interval());
  return x;
}

}  // namespace

TEST(TubeProperty, EvalOverIntervalMatchesDefinition) {
  std::mt19937_64 rng(17);
  for (int trial = 0; trial < 300; ++trial) {
    const Tube x = random_tube(rng);
    const auto& td = *x.tdomain();
    std::uniform_real_distribution<double> u(td.t0(), td.tf());
    double a = u(rng), b = u(rng);
    if (trial % 4 == 0) a = td.t(std::uniform_int_distribution<std::size_t>(0, td.nb_slices())(rng));
    if (a > b) std::swap(a, b);
    // definition: slices whose domain meets the interior (a, b), gates in [a, b]
    Interval expected = Interval::empty();
    if (a == b) {
      expected = x(a);
    } else {
      for (std::size_t k = 0; k < td.nb_slices(); ++k) {
        if (td.t(k) < b && td.t(k + 1) > a) expected |= x.slice(k);
      }
      for (std::size_t k = 0; k <= td.nb_slices(); ++k) {
        if (a <= td.t(k) && td.t(k) <= b) expected |= x.gate(k);
      }
    }
    const Interval got = x(Interval(a, b));
    ASSERT_EQ(got, expected) << "[t] = [" << a << ", " << b << "]";
    for (int i = 0; i < 20; ++i) {  // every [x](t) with t in [t] is inside
      const double t = a + (b - a) * std::uniform_real_distribution<double>(0, 1)(rng);
      if (t >= a && t <= b) {
        ASSERT_TRUE(x(t).is_subset(got));
      }
    }
  }
}

TEST(TubeProperty, InverseContainsEveryMeetingTime) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> c(-2.0, 2.0), r(0.0, 0.5);
  for (int trial = 0; trial < 300; ++trial) {
    const Tube x = random_tube(rng);
    const auto& td = *x.tdomain();
    const double m = c(rng), w = r(rng);
    const Interval y(m - w, m + w);
    std::vector<Interval> comps;
    const Interval inv = x.inverse(y, comps);
    for (std::size_t i = 1; i < comps.size(); ++i) {
      ASSERT_LE(comps[i - 1].ub(), comps[i].lb());  // sorted, at most touching
    }
    // every time point and random time whose value meets y is in a component
    std::vector<double> times(td.times().begin(), td.times().end());
    std::uniform_real_distribution<double> u(td.t0(), td.tf());
    for (int i = 0; i < 50; ++i) times.push_back(u(rng));
    for (double t : times) {
      const bool meets = x(t).intersects(y);
      bool in_comp = false;
      for (const auto& cpt : comps) in_comp = in_comp || cpt.contains(t);
      if (meets) {
        ASSERT_TRUE(inv.contains(t));
        ASSERT_TRUE(in_comp) << "t = " << t;
      }
      if (!td.is_time_point(t) && !in_comp) {
        ASSERT_FALSE(meets);
      }
    }
    // and every component meets y somewhere: at its gates or a slice inside
    for (const auto& cpt : comps) ASSERT_TRUE(x(cpt).intersects(y));
  }
}

TEST(TubeProperty, ConcurrentCopiesAttach) {
  auto td = TDomain::create(0.0, 1.0, 0.01);
  const Tube x(td, Interval(0, 1));
  std::vector<std::vector<Tube>> copies(4);
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i) {
    threads.emplace_back([&, i]() {
      for (int j = 0; j < 200; ++j) copies[static_cast<std::size_t>(i)].push_back(x);
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(td->nb_attached(), 801u);
  td->sample(0.005);
  for (const auto& v : copies) {
    for (const auto& c : v) ASSERT_EQ(c.nb_slices(), 101u);
  }
}
