#pragma once
// The network of the plaza1 example (real data): the error model and the
// solve up to the fixed point, shared by examples/cpp/plaza1.cpp and
// bench/bench_plaza1.cpp. One network, on the time points of the data (one
// slice per odometry period):
//   ψ(t_j) − ψ(t_i) ∈ Σ Δψ_k − b0 (t_j − t_i) + [−d, d] (t_j − t_i), b0 ∈ [−b, b] one unknown of
//     the whole run (the gyro's turn-on bias), d its in-run drift  (CtcBiasedIncrement)
//   ψ(t_{k+1}) − ψ(t_k) ∈ Δψ_k + δ_k [−b, b]        (CtcIncrement: |b0 + d(t)| <= b at any time;
//     its increments narrowed by CtcBiasedIncrement to Δψ_k − [b0] δ_k ± d δ_k as b0 is learnt)
//   ψ' ∈ [−ω_max, ω_max]                             (CtcDeriv: the slices of ψ)
//   ψ'' ∈ [−α, α]                                    (CtcSecondDeriv: the slices of ψ)
//   p(t_{k+1}) − p(t_k) ∈ d_k (cos, sin)(ψ over the slice ± track),
//     d_k ∈ (d_k [1 − ε, 1 + ε] + [−o, u]) ∩ [0, ∞)  (CtcHeading, both ways:
//                                                      positions and heading)
//   the same over windows of 40 s, with the heading relative to the window's
//     middle from the increments and |ψ''| <= α inside a slice  (CtcHeadingWindow)
//   v = s (cos, sin)(ψ + e), s ∈ [0, s_max], |e| ≤ track; p' = v  (pointwise; CtcDeriv: slices)
//   for each range j: q_j = p(t_j), t_j ∈ stamp ± τ  (CtcEval)
//                     |q_j − beacon| ∈ r_j − [−e_short, e_long] (on the box q_j)
//     the 3529 ranges as one CtcEvalList node (all true), or with q >= 0
//     outliers allowed among them, one CtcQEval node (at most q of them wrong).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <vector>

#include "example_check.h"
#include "plaza1_bounds.h"
#include "plaza1_data.h"
#include "slice_tube.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_biased_increment.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval_list.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/dynamics/ctc_qeval.h"
#include "sillage/dynamics/ctc_second_deriv.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/interval/elementary.h"

namespace plaza1 {

using namespace sillage;

// The error model: plaza1_bounds.h (the table of bounds and their sources).

// The position tube at the fixed point, and what it took.
struct Solution {
  std::shared_ptr<TubeVector> p;
  std::shared_ptr<Tube> psi;  // the heading
  std::shared_ptr<TubeVector> v;  // the velocity, p' = v
  std::shared_ptr<Interval> b0;   // the gyro's turn-on bias (rad/s; measured minus true rate)
  ContractStats stats;
  std::size_t nb_ranges = 0;
};

// The length of the windows of CtcHeadingWindow, s (--heading-window; 0: none):
// long enough for a path of tens of metres against position boxes of about 20 m,
// short enough for the lawn-mower legs and the gyro drift (docs/plaza1.md).
constexpr double kHeadingWindow = 40.0;

// The network (with the ranges if `with_ranges`; q >= 0: at most q of them
// wrong, one CtcQEval; CtcHeadingWindow over windows of `heading_window`
// seconds if > 0) at its fixed point.
// td: the time domain (nullptr: a new one on d.t); the pieces of solve_pieces share one, so that
// their tubes can be joined.
inline Solution solve(const example::Plaza1Data& d, const Bounds& b, bool with_ranges, int q = -1,
                      double heading_window = kHeadingWindow, std::shared_ptr<TDomain> td = nullptr) {
  using example::slice_tube;
  if (!td) td = TDomain::create(d.t);
  const std::size_t n = td->nb_slices();
  std::vector<Interval> dpsi(n), dist(n), measured(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Interval w = td->slice_width(k);
    measured[k] = Interval(d.dpsi_drift[k]);
    dpsi[k] = Interval(d.dpsi_drift[k]) + w * Interval(-b.gyro_bias, b.gyro_bias);
    dist[k] = (Interval(d.dist[k]) * Interval(1 - b.dist_rel, 1 + b.dist_rel) + Interval(-b.dist_over, b.dist_under)) &
              Interval(0, INFINITY);
  }
  auto psi = std::make_shared<Tube>(td);
  psi->set_gate(0, Interval(b.start_heading) + Interval(-b.heading0, b.heading0));
  auto dpsi_t = std::make_shared<Tube>(slice_tube(td, dpsi));
  auto dist_t = std::make_shared<Tube>(slice_tube(td, dist));
  auto omega = std::make_shared<Tube>(td, Interval(-b.turn_max, b.turn_max));
  auto speed = std::make_shared<Tube>(td, Interval(0, b.speed_max));
  auto track = std::make_shared<Tube>(td, Interval(-b.track, b.track));
  auto v = std::make_shared<TubeVector>(td, 2);
  Solution s;
  s.p = std::make_shared<TubeVector>(td, 2);
  s.p->set_gate(0, IntervalVector{{b.start_x - b.pos0, b.start_x + b.pos0}, {b.start_y - b.pos0, b.start_y + b.pos0}});

  ContractorNetwork cn;
  s.b0 = std::make_shared<Interval>(-b.gyro_bias, b.gyro_bias);
  cn.add(std::make_shared<CtcIncrement>(), {psi, dpsi_t});
  // The gyro's bias is one unknown b0 of the run plus an in-run drift: every span learns b0, and b0
  // narrows the heading everywhere, and the increments dpsi that CtcIncrement and the windows read. A drift as large as the bias class states nothing more than the
  // bias free at every step (CtcIncrement above): no contractor then.
  if (b.gyro_drift < b.gyro_bias) {
    const auto measured_t = std::make_shared<Tube>(slice_tube(td, measured));
    cn.add(std::make_shared<CtcBiasedIncrement>(b.gyro_drift), {psi, s.b0, measured_t, dpsi_t});
  }
  cn.add(std::make_shared<CtcDeriv>(), {psi, omega});
  // |ψ''| <= α: inside a period the heading stays within α δ² / 8 of the chord of its gates
  // (an unbounded α states nothing: no contractor then).
  if (std::isfinite(b.turn_accel)) {
    cn.add(std::make_shared<CtcSecondDeriv>(), {psi, std::make_shared<Tube>(td, Interval(-b.turn_accel, b.turn_accel))});
  }
  // The odometry increments, both ways: the heading gives the positions, the positions the heading.
  cn.add(std::make_shared<CtcHeading>(b.track), {s.p, psi, dist_t, omega});
  // The same over windows of heading_window seconds, one every quarter of a window: the heading
  // from the direction of travel measured by the positions, against the gyro's relative heading.
  if (heading_window > 0) {
    const double dt = (d.t.back() - d.t.front()) / static_cast<double>(n);
    const auto stride = static_cast<std::size_t>(std::max(1.0, std::round(heading_window / 4 / dt)));
    cn.add(std::make_shared<CtcHeadingWindow>(heading_window, b.track, b.turn_accel, stride),
           {s.p, psi, dist_t, dpsi_t, omega});
  }
  cn.add(std::make_shared<CtcFunction>(Function({"a", "s", "h", "e"}, "a - s*cos(h + e)")),
         {DomainRef::component(v, 0), speed, psi, track});
  cn.add(std::make_shared<CtcFunction>(Function({"a", "s", "h", "e"}, "a - s*sin(h + e)")),
         {DomainRef::component(v, 1), speed, psi, track});
  cn.add(std::make_shared<CtcDeriv>(), {s.p, v});
  // Named, as in plaza1.py, so that an empty network says which domain emptied.
  cn.set_name(s.p, "p");
  cn.set_name(v, "v");
  cn.set_name(psi, "psi");
  // The gyro's turn-on bias, when in the network: what empties a wrong piece of the start heading.
  if (b.gyro_drift < b.gyro_bias) cn.set_name(s.b0, "b0");

  if (with_ranges) {
    std::vector<TubeObservation> obs;
    std::map<int, Function> dist_to;  // per beacon, parsed once: ranges to one beacon share it
    for (std::size_t j = 0; j < d.rt.size(); ++j) {
      const Interval tj = Interval(d.rt[j] - b.time_err, d.rt[j] + b.time_err) & td->t0_tf();
      if (tj.is_empty()) continue;
      const int id = static_cast<int>(d.rid[j]);
      const auto [bx, by] = d.beacons.at(id);
      const Interval range = Interval(d.r[j] - b.range_long, d.r[j] + b.range_short) & Interval(0, INFINITY);
      auto f = dist_to.find(id);
      if (f == dist_to.end()) {
        f = dist_to.emplace(id, Function({"q1", "q2"}, "sqrt((q1 - " + number_text(bx) + ")^2 + (q2 - " +
                                                            number_text(by) + ")^2)")).first;
      }
      const auto ring = std::make_shared<CtcFunction>(f->second, range);
      // Named, so that an empty network says which range was inconsistent.
      char name[80];
      std::snprintf(name, sizeof name, "range %zu: beacon %d seen at t = %.2f", s.nb_ranges, static_cast<int>(d.rid[j]),
                    d.rt[j]);
      obs.push_back({tj, IntervalVector(2), ring, name});
      ++s.nb_ranges;
    }
    // All true (one node for all of them), or at most q wrong.
    // None within the run (another recording): nothing to add.
    if (!obs.empty() && q >= 0) cn.add(std::make_shared<CtcQEval>(q, std::move(obs)), {s.p, v});
    else if (!obs.empty()) cn.add(std::make_shared<CtcEvalList>(std::move(obs)), {s.p, v});
  }
  s.psi = psi;
  s.v = v;
  s.stats = cn.contract();
  return s;
}

// The start heading cut into pieces (--start-heading-pieces N): [start_heading ± heading0] as N
// equal intervals, each given as its centre and half-width. An unknown start heading [−π, π] is
// one interval of the network, whose gates grow wider than a turn with the gyro's increments: a
// window whose cells lie a turn apart then keeps the whole gate and learns nothing. Pieces
// narrower than a turn keep their gates apart until the windows learn (docs/plaza1.md).
inline std::vector<Bounds> start_heading_pieces(const Bounds& b, int pieces) {
  std::vector<Bounds> r;
  const double lb = b.start_heading - b.heading0, w = 2 * b.heading0 / pieces;
  for (int i = 0; i < pieces; ++i) {
    Bounds piece = b;
    piece.start_heading = lb + (i + 0.5) * w;
    piece.heading0 = w / 2;
    r.push_back(piece);
  }
  return r;
}

// One piece of the start heading: its start interval, its network at the fixed point, its CPU time.
struct Piece {
  Interval start;
  Solution sol;
  double cpu = 0;
};

// The network once per piece of the start heading (start_heading_pieces), one after the other,
// on one time domain. `hull` is the hull of the non-empty pieces, gate by gate and slice by
// slice: every solution starts in some piece, so it is a guaranteed enclosure. Its stats add up
// all the pieces' rounds and runs; if every piece is empty, hull.stats is the first piece's
// (empty) and each piece's explanation is in `pieces`.
struct PieceSolution {
  Solution hull;
  std::vector<Piece> pieces;
};

inline PieceSolution solve_pieces(const example::Plaza1Data& d, const Bounds& b, bool with_ranges, int q = -1,
                                  double heading_window = kHeadingWindow, int pieces = 1) {
  const auto td = TDomain::create(d.t);
  PieceSolution r;
  for (const Bounds& piece : start_heading_pieces(b, pieces)) {
    const double start = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
    Solution s = solve(d, piece, with_ranges, q, heading_window, td);
    const double cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC - start;
    r.pieces.push_back({Interval(piece.start_heading) + Interval(-piece.heading0, piece.heading0), s, cpu});
  }
  Solution& h = r.hull;
  ContractStats total;
  for (const Piece& piece : r.pieces) {
    const Solution& s = piece.sol;
    total.iterations += s.stats.iterations, total.contractor_calls += s.stats.contractor_calls;
    total.time += s.stats.time;
    if (s.stats.empty) continue;
    if (!h.p) {  // the first non-empty piece: copies, joined with the next ones
      h = s;
      h.p = std::make_shared<TubeVector>(*s.p), h.psi = std::make_shared<Tube>(*s.psi);
      h.v = std::make_shared<TubeVector>(*s.v), h.b0 = std::make_shared<Interval>(*s.b0);
    } else {
      *h.p |= *s.p, *h.psi |= *s.psi, *h.v |= *s.v, *h.b0 |= *s.b0;
    }
  }
  if (!h.p) h = r.pieces.front().sol;  // every piece empty: no solution (each piece says why)
  h.stats.iterations = total.iterations, h.stats.contractor_calls = total.contractor_calls, h.stats.time = total.time;
  return r;
}

}  // namespace plaza1
