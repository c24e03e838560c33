#pragma once
// Loops of a robot on real data (thesis ch. 6): the pieces shared by the
// loops_* examples. A velocity tube in the world frame is built slice by
// slice from bounds on the speed and the heading; two checks against the
// ground truth say whether those bounds are honest:
//  - the integral check: the true displacement p(t2) - p(t1) = ∫_{t1}^{t2} v*
//    must lie in ∫_{t1}^{t2} [v] for every pair (t1, t2), since every loop
//    proof assumes it;
//  - the loop check: every true crossing of the path must lie in a detection
//    of the t-plane, and every proven loop must hold a true crossing.
// The ground truth is a sampled path with errors of its own: both checks
// accept a stated tolerance (in metres, in seconds) and also report the
// exact figures.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <ctime>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sillage/interval/elementary.h"
#include "sillage/loops/path_crossings.h"
#include "sillage/loops/tplane.h"
#include "sillage/tube/tube_integral.h"
#include "sillage/tube/tube_vector.h"
#include "slice_tube.h"

namespace example {

using sillage::Interval;
using sillage::IntervalVector;

// A sampled planar path (the ground truth).
struct Path {
  std::vector<double> t, x, y;
};

// v(k) = s(k) (cos ψ(k), sin ψ(k)) in interval arithmetic, slice by slice:
// it holds every velocity whose speed lies in [s](k) and heading in [ψ](k).
inline sillage::TubeVector velocity_tube(const std::shared_ptr<sillage::TDomain>& td,
                                         const std::vector<Interval>& speed, const std::vector<Interval>& heading) {
  if (speed.size() != td->nb_slices() || heading.size() != td->nb_slices()) {
    throw sillage::DimensionError("velocity_tube: one speed and one heading per slice expected");
  }
  std::vector<Interval> vx(speed.size()), vy(speed.size());
  for (std::size_t k = 0; k < speed.size(); ++k) {
    vx[k] = speed[k] * sillage::cos(heading[k]);
    vy[k] = speed[k] * sillage::sin(heading[k]);
  }
  return sillage::TubeVector(std::vector<sillage::Tube>{slice_tube(td, vx), slice_tube(td, vy)});
}

// The points of a path at least `step` apart (the first and last kept): it
// removes the jitter of a standing robot, which would count as crossings.
inline Path thinned(const Path& p, double step) {
  Path r;
  for (std::size_t i = 0; i < p.t.size(); ++i) {
    const bool last = i + 1 == p.t.size();
    if (!r.t.empty() && !last && std::hypot(p.x[i] - r.x.back(), p.y[i] - r.y.back()) < step) continue;
    r.t.push_back(p.t[i]), r.x.push_back(p.x[i]), r.y.push_back(p.y[i]);
  }
  return r;
}

// ---- integral check ----

struct IntegralCheck {
  std::size_t nb_pairs = 0;
  std::size_t nb_inside = 0;  // exactly inside
  std::size_t nb_within_5cm = 0, nb_within_20cm = 0;
  std::size_t nb_inside_tol = 0;  // inside the integral widened by the tolerance
  double max_gap = 0;             // largest distance (per component) from the truth to the integral
  double worst_t1 = 0, worst_t2 = 0;
};

// Pairs (i, j), i < j, of path samples: every `stride`-th sample with every
// other such sample, and every pair closer than `short_span` seconds among
// every `short_stride`-th sample.
inline std::vector<std::pair<std::size_t, std::size_t>> check_pairs(const Path& p, std::size_t stride,
                                                                    double short_span, std::size_t short_stride = 1) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  const std::size_t n = p.t.size();
  for (std::size_t i = 0; i < n; i += stride) {
    for (std::size_t j = i + stride; j < n; j += stride) pairs.push_back({i, j});
  }
  for (std::size_t i = 0; i < n; i += short_stride) {
    for (std::size_t j = i + short_stride; j < n && p.t[j] - p.t[i] <= short_span; j += short_stride) {
      if (i % stride != 0 || j % stride != 0) pairs.push_back({i, j});
    }
  }
  return pairs;
}

namespace detail {
// Distance from the interval d to the integral [I], 0 if inside; infinite
// when [I] is empty or unbounded (being inside it proves nothing).
inline double gap(const Interval& integral, const Interval& d) {
  if (integral.is_empty() || integral.is_unbounded()) return std::numeric_limits<double>::infinity();
  return std::max({0.0, integral.lb() - d.ub(), d.lb() - integral.ub()});
}
}  // namespace detail

// The true displacements of the pairs (sample indices of p) and the true
// crossings (displacement 0 between t1 and t2) against ∫_{t1}^{t2} [v].
// Times outside v's domain are skipped.
inline IntegralCheck check_integrals(const sillage::TubeVector& v, const Path& p,
                                     const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                                     const std::vector<sillage::PathCrossing>& crossings, double tolerance) {
  const sillage::TubeAnalysis ax(v[0]), ay(v[1]);
  const Interval dom = v.tdomain()->t0_tf();
  IntegralCheck c;
  auto check = [&](double t1, double t2, const Interval& dx, const Interval& dy) {
    if (!dom.contains(t1) || !dom.contains(t2)) return;
    const double g = std::max(detail::gap(ax.integral(t1, t2), dx), detail::gap(ay.integral(t1, t2), dy));
    ++c.nb_pairs;
    c.nb_inside += g == 0.0;
    c.nb_within_5cm += g <= 0.05;
    c.nb_within_20cm += g <= 0.2;
    c.nb_inside_tol += g <= tolerance;
    if (g > c.max_gap) c.max_gap = g, c.worst_t1 = t1, c.worst_t2 = t2;
  };
  for (const auto& [i, j] : pairs) {
    check(p.t[i], p.t[j], Interval(p.x[j]) - Interval(p.x[i]), Interval(p.y[j]) - Interval(p.y[i]));
  }
  for (const auto& x : crossings) check(x.t1, x.t2, Interval(0.0), Interval(0.0));
  return c;
}

// ---- loop check ----

struct LoopCheck {
  std::size_t nb_crossings = 0;
  std::size_t in_detection = 0;                     // inside some detection (must be all)
  std::size_t in_complete = 0;                      // ... a complete one
  std::size_t in_proven = 0;                        // ... a proven one
  std::size_t proven = 0;                           // loops proven by T
  std::size_t proven_hit = 0;                       // ... holding a true crossing (must be all)
  std::size_t newton = 0, newton_hit = 0;           // the same for N
  std::size_t degree_zero = 0;                      // complete detections of degree 0 (no proof either way from T)
  std::size_t degree_unknown = 0;                   // complete detections whose degree is undetermined
  std::size_t counted = 0;                          // proven loops whose count is known
  std::size_t count_sum = 0;                        // sum of the counts
  std::size_t count_match = 0;                      // ... equal to the crossings inside
  double proven_span_min = 0, proven_span_max = 0;  // range of t2 - t1 over the proven loops (s)
  std::vector<std::size_t> missed_proofs;           // detections proven but holding no crossing
};

namespace detail {
inline bool holds(const sillage::Loop& l, const sillage::PathCrossing& x, double tol) {
  const IntervalVector& h = l.t_box();
  if (x.t1 < h[0].lb() - tol || x.t1 > h[0].ub() + tol || x.t2 < h[1].lb() - tol || x.t2 > h[1].ub() + tol) {
    return false;
  }
  for (const IntervalVector& b : l.boxes()) {
    if (x.t1 >= b[0].lb() - tol && x.t1 <= b[0].ub() + tol && x.t2 >= b[1].lb() - tol && x.t2 <= b[1].ub() + tol) {
      return true;
    }
  }
  return false;
}
}  // namespace detail

// `tol`: seconds by which the boxes are widened (the time resolution of the
// ground truth).
inline LoopCheck check_loops(const sillage::TPlane& tp, const std::vector<sillage::PathCrossing>& crossings,
                             double tol) {
  LoopCheck c;
  c.nb_crossings = crossings.size();
  const auto& loops = tp.detections();
  std::vector<std::size_t> inside(loops.size(), 0);
  for (const auto& x : crossings) {
    bool any = false, complete = false, proven = false;
    for (std::size_t i = 0; i < loops.size(); ++i) {
      if (!detail::holds(loops[i], x, tol)) continue;
      any = true, complete |= loops[i].complete(), proven |= loops[i].proven();
      ++inside[i];
    }
    c.in_detection += any, c.in_complete += complete, c.in_proven += proven;
  }
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const sillage::Loop& l = loops[i];
    if (l.complete() && !l.degree()) ++c.degree_unknown;
    if (l.complete() && l.degree() && *l.degree() == 0) ++c.degree_zero;
    if (l.proven()) {
      const double span = l.t_box()[1].mid() - l.t_box()[0].mid();
      c.proven_span_min = c.proven == 0 ? span : std::min(c.proven_span_min, span);
      c.proven_span_max = c.proven == 0 ? span : std::max(c.proven_span_max, span);
      ++c.proven;
      if (inside[i] > 0)
        ++c.proven_hit;
      else
        c.missed_proofs.push_back(i);
    }
    if (l.proven_newton()) ++c.newton, c.newton_hit += inside[i] > 0;
    if (l.proven() && l.count()) {
      ++c.counted, c.count_sum += *l.count();
      c.count_match += *l.count() == inside[i];
    }
  }
  return c;
}

inline bool passed(const LoopCheck& c) {
  return c.in_detection == c.nb_crossings && c.proven_hit == c.proven && c.newton_hit == c.newton;
}

// The t-plane of v at precision eps (seconds), its proofs, the loop check
// against the true crossings (tolerance tol seconds) and the time taken.
struct LoopRun {
  sillage::TPlane tplane;
  LoopCheck check;
  double seconds = 0, cpu = 0;  // detections and proofs: wall time, CPU time of all threads
  double detect_seconds = 0;    // wall time of the detections alone
};

inline LoopRun run_loops(const std::shared_ptr<sillage::TDomain>& td, double eps, const sillage::TubeVector& v,
                         const std::vector<sillage::PathCrossing>& crossings, double tol) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  LoopRun r{sillage::TPlane(td), {}, 0, 0, 0};
  r.tplane.compute_detections(eps, v);
  r.detect_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.tplane.compute_proofs(v);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  r.check = check_loops(r.tplane, crossings, tol);
  return r;
}

// Prints one block of results; `label` names the velocity model.
inline void print_loops(const std::string& label, const LoopRun& run, const IntegralCheck& ic, double tol_m) {
  const sillage::TPlane& tp = run.tplane;
  const LoopCheck& c = run.check;
  const std::size_t n = tp.nb_detections(), nc = tp.nb_complete_detections();
  std::printf("%s\n", label.c_str());
  const auto pct = [&](std::size_t k) { return 100.0 * static_cast<double>(k) / static_cast<double>(ic.nb_pairs); };
  std::printf(
      "  integral check, %zu pairs: truth inside %.2f %%, within 5 cm %.2f %%, 20 cm %.2f %%, %.2f m %.2f %%;"
      " largest miss %.3f m at (%.2f, %.2f)\n",
      ic.nb_pairs, pct(ic.nb_inside), pct(ic.nb_within_5cm), pct(ic.nb_within_20cm), tol_m, pct(ic.nb_inside_tol),
      ic.max_gap, ic.worst_t1, ic.worst_t2);
  std::printf(
      "  detections %zu: complete %zu (degree 0: %zu, undetermined: %zu), touching the border or the diagonal %zu\n", n,
      nc, c.degree_zero, c.degree_unknown, n - nc);
  std::printf("  proofs: T %zu, N %zu; counted %zu, loops counted %zu (equal to the crossings inside: %zu)\n",
              tp.nb_proofs(), tp.nb_newton_proofs(), c.counted, c.count_sum, c.count_match);
  std::printf("  true crossings %zu: in detections %zu, in complete ones %zu, in proven ones %zu\n", c.nb_crossings,
              c.in_detection, c.in_complete, c.in_proven);
  std::printf("  proven loops holding a true crossing: T %zu / %zu, N %zu / %zu%s\n", c.proven_hit, c.proven,
              c.newton_hit, c.newton, passed(c) ? "" : "  <-- TRUTH CHECK FAILED");
  if (c.proven > 0) std::printf("  proven loops last %.0f s to %.0f s\n", c.proven_span_min, c.proven_span_max);
  for (std::size_t i : c.missed_proofs) {
    const IntervalVector& h = tp.detections()[i].t_box();
    std::printf("    proven, no crossing: [%.2f, %.2f] x [%.2f, %.2f]\n", h[0].lb(), h[0].ub(), h[1].lb(), h[1].ub());
  }
  std::printf("  time of detections and proofs: %.2f s wall (detections %.2f s), %.2f s CPU (all threads)\n",
              run.seconds, run.detect_seconds, run.cpu);
}

}  // namespace example
