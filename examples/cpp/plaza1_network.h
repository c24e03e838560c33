#pragma once
// The networks of the plaza1 example (real data): the error model and the
// solve up to the fixed point, shared by examples/cpp/plaza1.cpp and
// bench/bench_plaza1.cpp. The network, on the time points of the data (one
// slice per odometry period):
//   ψ(t_{k+1}) − ψ(t_k) ∈ Δψ_k + δ_k [−b, b]        (CtcIncrement: gyro bias b)
//   ψ' ∈ [−ω_max, ω_max]                             (CtcDeriv: the slices of ψ)
//   i(k) = d (cos [ψ](k), sin [ψ](k)), d ∈ d_k [1 − ε, 1 + ε] + [−a, a]  (slice by slice)
//   p(t_{k+1}) − p(t_k) ∈ i(k)                       (CtcIncrement)
//   v = s (cos ψ, sin ψ), s ∈ [0, s_max]; p' = v     (pointwise; CtcDeriv: slices)
//   for each range j: q_j = p(t_j), t_j ∈ stamp ± τ  (CtcEval)
//                     |q_j − beacon| ∈ r_j − [−e_short, e_long] (pointwise on the box q_j)
// ∫ d cos ψ over a slice lies in d_k cos([ψ](k)) since the speed is >= 0.
// With b.feedback_window > 0, heading_from_positions contracts the heading
// gates from the position boxes over windows of slices, and both networks run
// again, up to b.feedback_rounds times (stats: those of the last run).
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "example_check.h"
#include "plaza1_bounds.h"
#include "plaza1_data.h"
#include "slice_tube.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/interval/elementary.h"

namespace plaza1 {

using namespace sillage;

// The error model: plaza1_bounds.h (the table of bounds and their sources).

// The position tube at the fixed point, and what it took.
struct Solution {
  std::shared_ptr<TubeVector> p;
  std::shared_ptr<Tube> psi;  // the heading
  std::size_t feedback_rounds = 0, feedback_gates = 0;  // heading from positions: rounds, gates contracted
  ContractStats stats;
  std::size_t nb_ranges = 0;
};

// Heading from positions, over windows of slices [k, m]:
//   p(t_m) - p(t_k) = sum_j inc_j, inc_j in dist_j (cos(psi(t_k) + R_j), sin(psi(t_k) + R_j)),
// R_j enclosing psi(t) - psi(t_k) on slice j (and the direction of travel off the heading by
// at most b.track): the odometry heading changes since t_k, the turn inside slice j (within
// turn_accel delta^2 / 8 of the chord between its gates) and the track error. With
// V = sum_j dist_j (cos R_j, sin R_j), p(t_m) - p(t_k) in Rot(psi(t_k)) V: the cells of
// [psi](t_k) whose rotated V misses [p](t_m) - [p](t_k) are removed. Returns the number of
// gates contracted.
inline std::size_t heading_from_positions(const TDomain& td, Tube& psi, const TubeVector& p,
                                          const std::vector<Interval>& dpsi, const std::vector<Interval>& dist,
                                          const Bounds& b) {
  const std::size_t n = td.nb_slices();
  std::size_t changed = 0;
  for (std::size_t k = 0; k < n; k += b.feedback_stride) {
    // the window: slices k .. m-1, t_m - t_k >= feedback_window
    std::size_t m = k;
    while (m < n && td.t(m) - td.t(k) < b.feedback_window) ++m;
    if (m == k) break;
    Interval vx(0.0), vy(0.0), rel(0.0);  // rel: psi(t_j) - psi(t_k)
    for (std::size_t j = k; j < m; ++j) {
      const double w = td.t(j + 1) - td.t(j);
      const Interval inside = (Interval(0.0) | dpsi[j]) + Interval(-1, 1) * (b.turn_accel * w * w / 8 + b.track);
      const Interval r = rel + inside;
      vx += dist[j] * cos(r), vy += dist[j] * sin(r);
      rel += dpsi[j];
    }
    const Interval dx = p[0].gate(m) - p[0].gate(k), dy = p[1].gate(m) - p[1].gate(k);
    const Interval g = psi.gate(k);
    if (g.is_empty() || g.is_unbounded()) continue;
    const int cells = std::max(1, static_cast<int>(std::ceil(g.diam() / b.feedback_cell)));
    Interval kept = Interval::empty();
    for (int c = 0; c < cells; ++c) {
      // the cells cover [g] exactly: the ends are g's, neighbours share their bound
      const double lo = c == 0 ? g.lb() : g.lb() + g.diam() * c / cells;
      const double hi = c + 1 == cells ? g.ub() : g.lb() + g.diam() * (c + 1) / cells;
      const Interval th(lo, hi);
      const Interval co = cos(th), si = sin(th);
      const Interval rx = co * vx - si * vy, ry = si * vx + co * vy;
      if (!(rx & dx).is_empty() && !(ry & dy).is_empty()) kept |= th;
    }
    kept &= g;
    if (kept.is_empty() || kept.diam() < g.diam() * 0.99) {
      psi.set_gate(k, kept);
      ++changed;
    }
  }
  return changed;
}

// The heading network, then the position network (with the ranges if
// `with_ranges`), each to its fixed point.
inline Solution solve(const example::Plaza1Data& d, const Bounds& b, bool with_ranges) {
  using example::slice_tube;
  const auto td = TDomain::create(d.t);
  const std::size_t n = td->nb_slices();
  std::vector<Interval> dpsi(n), dist(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Interval w = td->slice_width(k);
    dpsi[k] = Interval(d.dpsi_drift[k]) + w * Interval(-b.gyro_bias, b.gyro_bias);
    dist[k] = (Interval(d.dist[k]) * Interval(1 - b.dist_rel, 1 + b.dist_rel) + Interval(-b.dist_over, b.dist_under)) &
              Interval(0, INFINITY);
  }
  auto psi = std::make_shared<Tube>(td);
  psi->set_gate(0, Interval(b.start_heading) + Interval(-b.heading0, b.heading0));
  auto dpsi_t = std::make_shared<Tube>(slice_tube(td, dpsi));
  auto omega = std::make_shared<Tube>(td, Interval(-b.turn_max, b.turn_max));
  auto speed = std::make_shared<Tube>(td, Interval(0, b.speed_max));
  auto v = std::make_shared<TubeVector>(td, 2);
  Solution s;
  s.p = std::make_shared<TubeVector>(td, 2);
  s.p->set_gate(0, IntervalVector{{b.start_x - b.pos0, b.start_x + b.pos0}, {b.start_y - b.pos0, b.start_y + b.pos0}});

  // The heading first; the positions flow back to it only through
  // heading_from_positions (b.feedback_window > 0), between the networks.
  ContractorNetwork heading;
  heading.add(std::make_shared<CtcIncrement>(), {psi, dpsi_t});
  heading.add(std::make_shared<CtcDeriv>(), {psi, omega});
  // Empty: psi is empty, and the position network reports it empty on input.
  example::check_stats(heading.contract(), "heading");
  // Increments of p over each slice: per-slice quantities, not values of a
  // continuous function of time, so computed slice by slice (not as a tube
  // constraint, whose gates would tie neighbouring slices together).
  std::vector<Interval> inc1(n), inc2(n);
  const auto increments = [&] {
    for (std::size_t k = 0; k < n; ++k) {
      inc1[k] = dist[k] * cos(psi->slice(k));
      inc2[k] = dist[k] * sin(psi->slice(k));
    }
  };
  increments();
  auto inc = std::make_shared<TubeVector>(std::vector<Tube>{slice_tube(td, inc1), slice_tube(td, inc2)});

  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(Function({"a", "s", "h"}, "a - s*cos(h)")),
         {DomainRef::component(v, 0), speed, psi});
  cn.add(std::make_shared<CtcFunction>(Function({"a", "s", "h"}, "a - s*sin(h)")),
         {DomainRef::component(v, 1), speed, psi});
  cn.add(std::make_shared<CtcIncrement>(), {s.p, inc});
  cn.add(std::make_shared<CtcDeriv>(), {s.p, v});

  if (with_ranges) {
    const auto eval = std::make_shared<CtcEval>();
    for (std::size_t j = 0; j < d.rt.size(); ++j) {
      const Interval tj = Interval(d.rt[j] - b.time_err, d.rt[j] + b.time_err) & td->t0_tf();
      if (tj.is_empty()) continue;
      const auto [bx, by] = d.beacons.at(static_cast<int>(d.rid[j]));
      const Interval range = Interval(d.r[j] - b.range_long, d.r[j] + b.range_short) & Interval(0, INFINITY);
      const Function dist_to_beacon({"q1", "q2"}, "sqrt((q1 - " + number_text(bx) + ")^2 + (q2 - " +
                                                      number_text(by) + ")^2)");
      const auto q = std::make_shared<IntervalVector>(2);
      cn.add(eval, {std::make_shared<Interval>(tj), q, s.p, v});
      cn.add(std::make_shared<CtcFunction>(dist_to_beacon, range), {q});
      ++s.nb_ranges;
    }
  }
  s.psi = psi;
  s.stats = cn.contract();
  if (b.feedback_window > 0 && !s.stats.empty) {
    for (int round = 0; round < b.feedback_rounds; ++round) {
      const std::size_t changed = heading_from_positions(*td, *psi, *s.p, dpsi, dist, b);
      if (changed == 0) break;
      ++s.feedback_rounds, s.feedback_gates += changed;
      s.stats = heading.contract();
      if (!example::check_stats(s.stats, "heading")) break;
      increments();
      for (std::size_t k = 0; k < n; ++k) (*inc)[0].set(inc1[k], k), (*inc)[1].set(inc2[k], k);
      s.stats = cn.contract();
      if (s.stats.empty) break;
    }
  }
  return s;
}

}  // namespace plaza1
