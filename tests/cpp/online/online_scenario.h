#pragma once
// A robot for the online tests: p(t) = (10 cos(t/10), 10 sin(t/5)), its
// velocity measured per period within ±0.05, ranges to three beacons within
// ±0.1 m, stamped within ±0.1 s, arriving 0.3 s late. The truth is known
// exactly (interval evaluation of the formulas), so tests can check that it
// stays inside every estimate.
#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#include "sillage/ctc/ctc_function.h"
#include "sillage/interval/elementary.h"
#include "sillage/online/online_estimator.h"

namespace sillage::test {

inline IntervalVector truth(const Interval& t) {
  return IntervalVector{10.0 * cos(t / 10.0), 10.0 * sin(t / 5.0)};
}
inline IntervalVector velocity(const Interval& t) {
  return IntervalVector{-sin(t / 10.0), 2.0 * cos(t / 5.0)};
}

struct Range {
  double arrival;  // when it reaches the estimator
  Interval t;      // its stamp +- 0.1 s
  std::shared_ptr<IntervalVector> beacon;
  std::shared_ptr<Interval> range;
};

struct Scenario {
  double t0 = 0.0, dt = 0.2;
  std::size_t steps = 300;
  std::vector<Range> ranges;  // in arrival order

  explicit Scenario(unsigned seed, std::size_t n_steps = 300) : steps(n_steps) {
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::vector<IntervalVector> beacons{{0.0, 0.0}, {20.0, 5.0}, {-5.0, 15.0}};
    const double tf = t0 + dt * static_cast<double>(steps);
    for (double t = t0 + 0.5; t < tf - 0.5; t += 0.3 + u(gen)) {
      const auto& b = beacons[static_cast<std::size_t>(u(gen) * 3) % 3];
      const IntervalVector p = truth(Interval(t));
      const Interval r = sqrt(sqr(p[0] - b[0]) + sqr(p[1] - b[1]));
      const double noise = 0.1 * (2 * u(gen) - 1), stamp = t + 0.1 * (2 * u(gen) - 1);
      ranges.push_back({t + 0.3, Interval(stamp - 0.1, stamp + 0.1), std::make_shared<IntervalVector>(b),
                        std::make_shared<Interval>(r + Interval(noise - 0.1, noise + 0.1))});
    }
  }
  double time(std::size_t k) const { return t0 + dt * static_cast<double>(k); }
  IntervalVector input(std::size_t k) const {  // the period [t_k-1, t_k]
    return velocity(Interval(time(k - 1), time(k))) + IntervalVector{Interval(-0.05, 0.05), Interval(-0.05, 0.05)};
  }
  static std::shared_ptr<const Ctc> range_ctc() {
    return std::make_shared<CtcFunction>(
        Function({"q0", "q1", "b0", "b1", "r"}, "sqrt((q0 - b0)^2 + (q1 - b1)^2) - r"));
  }
  std::unique_ptr<OnlineEstimator> estimator(OnlineOptions o) const {
    auto est = std::make_unique<OnlineEstimator>(t0, o);
    est->add_state("p", 2, start());
    est->add_input("v", 2);
    est->add_deriv("p", "v");
    return est;
  }
  IntervalVector start() const { return truth(Interval(t0)) + IntervalVector{Interval(-0.1, 0.1), Interval(-0.1, 0.1)}; }
  // Delivers everything: the periods in order, each range once time has
  // reached its arrival; `each` is called after every update.
  template <class F>
  void replay(OnlineEstimator& est, const std::vector<Range>& order, F&& each) const {
    std::size_t next = 0;
    for (std::size_t k = 1; k <= steps; ++k) {
      est.advance(time(k), {{"v", input(k)}});
      each();
      while (next < order.size() && order[next].arrival <= time(k)) {
        const Range& r = order[next++];
        est.observe(r.t, "p", range_ctc(), {r.beacon, r.range});
        each();
      }
    }
  }
};

}  // namespace sillage::test
