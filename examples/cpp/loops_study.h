#pragma once
// Why a true crossing is left unproven by TPlane::compute_proofs: a study of
// every complete detection whose crossings are not all in a proven detection
// or proven piece (docs/loops.md, "What is left"). Used by
// `example_loops_survey --study 1` on the survey and on the Lissajous mission.
//
// For each such crossing (t1, t2), with its orientation sign det J_f* =
// -sign(v*(t1) x v*(t2)) (the index of the zero: the degree of a small region
// around it), the reason is the first of:
//   InnerTwin     it lies in an Inner leaf (6.10) connected through Inner
//                 leaves to a crossing of opposite orientation, the crossings
//                 of that set adding up to 0: every point of the set is a
//                 feasible loop, so any boundary separating the two crosses it
//                 and no degree (nor Newton) test can prove either alone from
//                 this data (the ceiling);
//   FineTwin      the same once the other leaves of the detection are refined
//                 to eps/16 and tested Inner again (the Inner set of the
//                 paving at eps is only part of the feasible set); a twin at
//                 eps is counted InnerTwin only if it is still one at eps/16
//                 (merged groups may add up to a non-zero index);
//   MoreLevels    the split proves it with 8 levels instead of the 3 of
//                 ProofOptions (boxes of eps/16 instead of eps/2.8);
//   NoDeepMargin  ... with 8 levels and every box bisected (deep_margin 0);
//   FinerDegree   ... and the degree's edges refined to eps/10^4;
//   Deeper        ... with 14 levels (eps/128) and 2^20 boxes per piece;
//   Unseparated   none of these: its piece at eps/16 still holds a crossing
//                 of opposite orientation (or has an undetermined degree).
// The experiments rerun split_region (public) on the detection's leaves, the
// Inner ones kept whole as compute_proofs does.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "sillage/loops/component_split.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/path_crossings.h"
#include "sillage/loops/tplane.h"
#include "sillage/paving/component.h"

namespace loops_study {

using namespace sillage;

enum class Reason { InnerTwin, FineTwin, MoreLevels, NoDeepMargin, FinerDegree, Deeper, Unseparated };
inline constexpr std::array<const char*, 7> kReasonNames = {
    "inner twin", "fine twin", "more levels", "no deep margin", "finer degree", "deeper", "unseparated"};

using Velocity = std::function<std::array<double, 2>(double)>;

inline bool holds(const std::vector<IntervalVector>& boxes, const PathCrossing& c) {
  for (const IntervalVector& b : boxes) {
    if (b[0].contains(c.t1) && b[1].contains(c.t2)) return true;
  }
  return false;
}

// The index of the zero of f(t1, t2) = p(t2) - p(t1) at the crossing: the sign
// of det(-v(t1) | v(t2)) (0 for a tangential pass).
inline int orientation(const PathCrossing& c, const Velocity& velocity) {
  const auto a = velocity(c.t1), b = velocity(c.t2);
  const double cross = a[0] * b[1] - a[1] * b[0];
  return cross > 0 ? -1 : (cross < 0 ? 1 : 0);
}

// The crossing lies in a proven detection or a proven piece.
inline bool proven(const Loop& l, const PathCrossing& c) {
  if (l.proven()) return true;
  for (const Loop& p : l.pieces()) {
    if (p.proven() && holds(p.boxes(), c)) return true;
  }
  return false;
}

struct Totals {
  std::size_t in_complete = 0, proven = 0;
  std::array<std::size_t, 7> by_reason{};
};

class Study {
 public:
  Study(const TPlane& tplane, const TubeVector& v, const std::vector<PathCrossing>& truth, Velocity velocity,
        bool verbose)
      : tp_(tplane), f_(v), truth_(truth), velocity_(std::move(velocity)), verbose_(verbose) {
    for (const IntervalVector& b : tp_.paving().inner()) inner_.insert(key(b));
  }

  Totals run() {
    Totals t;
    for (std::size_t d = 0; d < tp_.detections().size(); ++d) {
      const Loop& l = tp_.detections()[d];
      if (!l.complete()) continue;
      std::vector<std::size_t> mine, left;
      for (std::size_t i = 0; i < truth_.size(); ++i) {
        if (!holds(l.boxes(), truth_[i])) continue;
        mine.push_back(i);
        if (!proven(l, truth_[i])) left.push_back(i);
      }
      t.in_complete += mine.size();
      t.proven += mine.size() - left.size();
      if (left.empty()) continue;
      for (Reason r : study(d, l, mine, left)) ++t.by_reason[static_cast<std::size_t>(r)];
    }
    return t;
  }

 private:
  using Key = std::tuple<double, double, double, double>;
  static Key key(const IntervalVector& b) { return {b[0].lb(), b[0].ub(), b[1].lb(), b[1].ub()}; }
  bool is_inner(const IntervalVector& b) const { return inner_.count(key(b)) > 0; }

  // The Inner group (connected Inner leaves of l) holding the crossing, -1 if none.
  static int group_of(const std::vector<Component>& groups, const PathCrossing& c) {
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (holds(groups[g].boxes, c)) return int(g);
    }
    return -1;
  }

  // (6.10) on a t-box: every point of it is a feasible loop.
  bool inner_test(const IntervalVector& t) const {
    if (!(t[0].ub() < t[1].lb())) return false;
    const auto [lower, upper] = f_.integral_bounds(t[0], t[1]);
    if (lower.is_empty() || upper.is_empty()) return false;
    for (std::size_t i = 0; i < 2; ++i) {
      if (!(lower[i].ub() <= 0.0 && 0.0 <= upper[i].lb())) return false;
    }
    return true;
  }

  // The Inner leaves of l, and the Inner boxes found by bisecting its other
  // leaves `levels` times (halves where 0 is not in [f] dropped).
  std::vector<IntervalVector> refined_inner(const Loop& l, std::size_t levels) const {
    std::vector<IntervalVector> inner, work;
    for (const IntervalVector& b : l.boxes()) (is_inner(b) ? inner : work).push_back(b);
    const PlaneFunction f = f_.function();
    for (std::size_t level = 0; level < levels && !work.empty(); ++level) {
      std::vector<IntervalVector> next;
      for (const IntervalVector& b : work) {
        auto [lo, hi] = b.bisect();
        for (IntervalVector* h : {&lo, &hi}) {
          const IntervalVector y = f(*h);
          if (!y[0].contains(0.0) || !y[1].contains(0.0)) continue;
          (inner_test(*h) ? inner : next).push_back(std::move(*h));
        }
      }
      work = std::move(next);
    }
    return inner;
  }

  // Per crossing of `mine`: twin when its Inner group (of `inner`) holds one of
  // opposite orientation and the group's orientations add up to 0.
  std::vector<bool> twins(const std::vector<IntervalVector>& inner, const std::vector<std::size_t>& mine,
                          const std::vector<int>& orient, std::vector<int>* group_out = nullptr) const {
    const std::vector<Component> groups = connected_components(inner);
    std::vector<int> group(mine.size());
    for (std::size_t k = 0; k < mine.size(); ++k) group[k] = group_of(groups, truth_[mine[k]]);
    std::vector<bool> twin(mine.size(), false);
    for (std::size_t k = 0; k < mine.size(); ++k) {
      int net = 0;
      bool opposite = false;
      for (std::size_t j = 0; j < mine.size() && group[k] >= 0; ++j) {
        if (group[j] != group[k]) continue;
        net += orient[j];
        opposite = opposite || orient[j] == -orient[k];
      }
      twin[k] = opposite && net == 0;
    }
    if (group_out) *group_out = group;
    return twin;
  }

  // The split of l under more refinement: for each variant, the crossings it proves.
  std::vector<bool> proven_by(const Loop& l, const std::vector<std::size_t>& left, std::size_t levels, double margin,
                              double edge_fraction, std::size_t max_boxes = ProofOptions{}.split_max_boxes) const {
    const double eps = tp_.eps();
    SplitOptions o;
    o.max_levels = levels;
    o.max_boxes = max_boxes;
    o.deep_margin = margin;
    o.degree.min_edge_length = edge_fraction * eps;
    o.count_options.min_width = ProofOptions{}.count_width_fraction * eps;
    o.inside = [this](const IntervalVector& b) { return is_inner(b); };
    const SplitResult r = split_region(l.boxes(), f_.memoized_function(), f_.jacobian_function(), o);
    std::vector<bool> out(left.size(), false);
    for (std::size_t k = 0; k < left.size(); ++k) {
      for (const SplitPiece& p : r.pieces) out[k] = out[k] || (p.proves_zero() && holds(p.boxes, truth_[left[k]]));
    }
    return out;
  }

  std::vector<Reason> study(std::size_t d, const Loop& l, const std::vector<std::size_t>& mine,
                            const std::vector<std::size_t>& left) const {
    std::vector<IntervalVector> inner_boxes;
    for (const IntervalVector& b : l.boxes()) {
      if (is_inner(b)) inner_boxes.push_back(b);
    }
    const std::size_t nb_groups = connected_components(inner_boxes).size();
    std::vector<int> group, orient(mine.size());
    for (std::size_t k = 0; k < mine.size(); ++k) orient[k] = orientation(truth_[mine[k]], velocity_);
    const std::vector<bool> twin = twins(inner_boxes, mine, orient, &group);
    const std::vector<bool> fine_twin = twins(refined_inner(l, 8), mine, orient);
    // The splits under more refinement, only for crossings that are no twins.
    bool separable = false;
    for (std::size_t k = 0, u = 0; k < mine.size() && u < left.size(); ++k) {
      if (left[u] != mine[k]) continue;
      separable = separable || !fine_twin[k];
      ++u;
    }
    const double eps = tp_.eps(), edge = ProofOptions{}.degree_edge_fraction;
    std::vector<bool> more(left.size(), false), no_margin = more, finer = more, deeper = more;
    if (separable) {
      more = proven_by(l, left, 8, SplitOptions{}.deep_margin, edge);
      no_margin = proven_by(l, left, 8, 0.0, edge);
      finer = proven_by(l, left, 8, 0.0, 1e-4);
      deeper = proven_by(l, left, 14, 0.0, 1e-4, std::size_t{1} << 20);
    }

    if (verbose_) {
      std::printf("\ndetection %zu  t in %s: %zu leaves (%zu inner, %zu inner groups), degree %s, count %s, "
                  "%zu true crossings, %zu unproven\n",
                  d, l.t_box().str().c_str(), l.boxes().size(), l.nb_inner(), nb_groups,
                  l.degree() ? std::to_string(*l.degree()).c_str() : "?",
                  l.count() ? std::to_string(*l.count()).c_str() : "?", mine.size(), left.size());
      for (std::size_t j = 0; j < l.pieces().size(); ++j) {
        const Loop& p = l.pieces()[j];
        std::size_t n = 0;
        int net = 0;
        for (std::size_t k = 0; k < mine.size(); ++k) {
          if (holds(p.boxes(), truth_[mine[k]])) ++n, net += orient[k];
        }
        std::printf("  piece %zu: %zu boxes (%.2f x %.2f eps), degree %s, count %s, %zu crossings (net %+d)\n", j,
                    p.boxes().size(), p.t_box()[0].diam() / eps, p.t_box()[1].diam() / eps,
                    p.degree() ? std::to_string(*p.degree()).c_str() : "?",
                    p.count() ? std::to_string(*p.count()).c_str() : "?", n, net);
      }
    }
    std::vector<Reason> reasons;
    for (std::size_t k = 0, u = 0; k < mine.size(); ++k) {
      const PathCrossing& c = truth_[mine[k]];
      if (u >= left.size() || left[u] != mine[k]) {
        if (verbose_) std::printf("  crossing (%.1f, %.1f) %+d group %d: proven\n", c.t1, c.t2, orient[k], group[k]);
        continue;
      }
      const Reason r = fine_twin[k]   ? (twin[k] ? Reason::InnerTwin : Reason::FineTwin)
                       : more[u]      ? Reason::MoreLevels
                       : no_margin[u] ? Reason::NoDeepMargin
                       : finer[u]     ? Reason::FinerDegree
                       : deeper[u]    ? Reason::Deeper
                                      : Reason::Unseparated;
      reasons.push_back(r);
      if (verbose_) {
        int piece = -1;
        for (std::size_t j = 0; j < l.pieces().size(); ++j) {
          if (holds(l.pieces()[j].boxes(), c)) piece = int(j);
        }
        std::printf("  crossing (%.1f, %.1f) %+d group %d piece %d: %s\n", c.t1, c.t2, orient[k], group[k], piece,
                    kReasonNames[static_cast<std::size_t>(r)]);
      }
      ++u;
    }
    return reasons;
  }

  const TPlane& tp_;
  LoopFunction f_;
  const std::vector<PathCrossing>& truth_;
  Velocity velocity_;
  bool verbose_;
  std::set<Key> inner_;
};

}  // namespace loops_study
