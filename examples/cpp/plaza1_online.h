#pragma once
// plaza1 online (docs/online.md): the network of plaza1_network.h as an
// OnlineEstimator, fed the log in stamp order as a robot would get it: the
// odometry of each period when it ends (advance), each range once time has
// reached its stamp (observe, its time the stamp ± 0.2 s). Shared by
// examples/cpp/plaza1_online.cpp and bench/bench_online.cpp.
//
// Not in the online form: the gyro's turn-on bias b0 (CtcBiasedIncrement),
// one unknown of the whole run (the bias free at every step instead, as in
// examples/problems/plaza1.toml).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "plaza1_bounds.h"
#include "plaza1_data.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/dynamics/ctc_second_deriv.h"
#include "sillage/error.h"
#include "sillage/online/online_estimator.h"

namespace plaza1 {

using namespace sillage;

// The plaza1 model, declared; the window W in seconds (inf: everything).
inline std::unique_ptr<OnlineEstimator> online_estimator(const example::Plaza1Data& d, const Bounds& b, double window,
                                                         double heading_window = 40.0) {
  OnlineOptions o;
  o.window = window;
  auto est = std::make_unique<OnlineEstimator>(d.t.front(), o);
  est->add_state("psi", 1, IntervalVector{Interval(b.start_heading) + Interval(-b.heading0, b.heading0)});
  est->add_state("p", 2, IntervalVector{{b.start_x - b.pos0, b.start_x + b.pos0}, {b.start_y - b.pos0, b.start_y + b.pos0}});
  est->add_state("v", 2);
  est->add_input("dpsi", 1);
  est->add_input("dist", 1);
  est->add_bounded("omega", IntervalVector{Interval(-b.turn_max, b.turn_max)});
  est->add_bounded("speed", IntervalVector{Interval(0, b.speed_max)});
  est->add_bounded("track", IntervalVector{Interval(-b.track, b.track)});
  est->add_bounded("alpha", IntervalVector{Interval(-b.turn_accel, b.turn_accel)});
  est->add(std::make_shared<CtcIncrement>(), {"psi", "dpsi"});
  est->add_deriv("psi", "omega");
  est->add(std::make_shared<CtcSecondDeriv>(), {"psi", "alpha"});
  est->add(std::make_shared<CtcHeading>(b.track), {"p", "psi", "dist", "omega"});
  if (heading_window > 0) {
    const double dt = (d.t.back() - d.t.front()) / static_cast<double>(d.t.size() - 1);
    const auto stride = static_cast<std::size_t>(std::max(1.0, std::round(heading_window / 4 / dt)));
    est->add(std::make_shared<CtcHeadingWindow>(heading_window, b.track, b.turn_accel, stride),
             {"p", "psi", "dist", "dpsi", "omega"});
  }
  est->add(std::make_shared<CtcFunction>(Function({"a", "s", "h", "e"}, "a - s*cos(h + e)")),
           {"v[0]", "speed", "psi", "track"});
  est->add(std::make_shared<CtcFunction>(Function({"a", "s", "h", "e"}, "a - s*sin(h + e)")),
           {"v[1]", "speed", "psi", "track"});
  est->add_deriv("p", "v");
  return est;
}

// What a replay measured: per update its latency, and per odometry time the
// online box of p (after every update at that time).
struct Replay {
  std::vector<double> latency;  // seconds, one per advance() or observe()
  // Seconds, one per advance(): an observe() whose time reaches past now is
  // held and returns at once, its work done by the advance that passes it.
  std::vector<double> advance_latency;
  std::vector<double> t;        // the odometry times t_1 .. t_N
  std::vector<IntervalVector> now;  // p at each of them, online
  std::size_t ranges = 0;
  bool consistent = true;
};

// Feeds the log through est in stamp order (`each_period`, if set, is called
// after each period's updates with its index k).
inline Replay replay(OnlineEstimator& est, const example::Plaza1Data& d, const Bounds& b,
                     const std::function<void(std::size_t)>& each_period = {}) {
  Replay r;
  std::vector<std::size_t> order(d.rt.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return d.rt[i] < d.rt[j]; });
  std::map<int, Function> dist_to;  // per beacon |q - beacon|, parsed once
  std::size_t next = 0;
  const auto clock = [] { return std::chrono::steady_clock::now(); };
  for (std::size_t k = 0; k + 1 < d.t.size(); ++k) {
    const Interval w = Interval(d.t[k + 1]) - Interval(d.t[k]);
    const Interval dpsi = Interval(d.dpsi_drift[k]) + w * Interval(-b.gyro_bias, b.gyro_bias);
    const Interval dist = (Interval(d.dist[k]) * Interval(1 - b.dist_rel, 1 + b.dist_rel) +
                           Interval(-b.dist_over, b.dist_under)) & Interval(0, INFINITY);
    auto start = clock();
    est.advance(d.t[k + 1], {{"dpsi", IntervalVector{dpsi}}, {"dist", IntervalVector{dist}}});
    r.latency.push_back(std::chrono::duration<double>(clock() - start).count());
    r.advance_latency.push_back(r.latency.back());
    for (; next < order.size() && d.rt[order[next]] <= d.t[k + 1]; ++next) {
      const std::size_t j = order[next];
      const Interval tj(d.rt[j] - b.time_err, d.rt[j] + b.time_err);
      if (tj.lb() < est.window_start()) continue;  // taken before the log's start
      const int id = static_cast<int>(d.rid[j]);
      auto f = dist_to.find(id);
      if (f == dist_to.end()) {
        const auto [bx, by] = d.beacons.at(id);
        f = dist_to.emplace(id, Function({"q1", "q2"}, "sqrt((q1 - " + number_text(bx) + ")^2 + (q2 - " +
                                                            number_text(by) + ")^2)")).first;
      }
      const Interval range = Interval(d.r[j] - b.range_long, d.r[j] + b.range_short) & Interval(0, INFINITY);
      start = clock();
      est.observe(tj, "p", std::make_shared<CtcFunction>(f->second, range));
      r.latency.push_back(std::chrono::duration<double>(clock() - start).count());
      ++r.ranges;
    }
    r.t.push_back(d.t[k + 1]);
    r.now.push_back(est.now("p"));
    r.consistent = r.consistent && est.last_update().summary.status != Status::NoSolution;
    if (each_period) each_period(k);
  }
  return r;
}

// The q-th quantile of the latencies (0 <= q <= 1), seconds.
inline double quantile(std::vector<double> x, double q) {
  if (x.empty()) return 0;
  const auto i = static_cast<std::size_t>(std::min(q * static_cast<double>(x.size()), static_cast<double>(x.size() - 1)));
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(i), x.end());
  return x[i];
}

}  // namespace plaza1
