// TPlane::compute_proofs: map boxes of the detections, then the zero tests
// of thesis 6.3 on the complete ones, in parallel over the components.
#include <tbb/parallel_for.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "sillage/error.h"
#include "sillage/loops/component_split.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/topological_degree.h"
#include "sillage/loops/tplane.h"
#include "sillage/loops/zero_tests.h"

namespace sillage {

namespace {

void check_options(const ProofOptions& o, double eps, const char* where) {
  if (!(o.degree_edge_fraction > 0) || !(o.count_width_fraction > 0)) {
    throw Error(std::string(where) + ": degree_edge_fraction and count_width_fraction must be > 0, got " +
                number_text(o.degree_edge_fraction) + " and " + number_text(o.count_width_fraction));
  }
  if (!(o.newton_inflation >= 0) || !std::isfinite(o.newton_inflation)) {
    throw Error(std::string(where) + ": newton_inflation must be finite and >= 0, got " +
                number_text(o.newton_inflation));
  }
  if (!(o.degree_edge_fraction * eps > 0) || !(o.count_width_fraction * eps > 0)) {
    throw Error(std::string(where) + ": the fractions of eps = " + number_text(eps) + " underflow to 0");
  }
  if (o.split && (o.split_max_levels == 0 || o.split_max_boxes == 0)) {
    throw Error(std::string(where) + ": split_max_levels and split_max_boxes must be positive, got " +
                std::to_string(o.split_max_levels) + " and " + std::to_string(o.split_max_boxes));
  }
}

// A detection of degree 0 or undetermined proves nothing, and an uncounted
// one does not say how many loops it holds: both may fall apart in pieces.
bool needs_split(const std::optional<int>& degree, const std::optional<std::size_t>& count, const ProofOptions& o) {
  return o.split && (!degree || *degree == 0 || (o.count && !count));
}

}  // namespace

void TPlane::compute_proofs(const TubeVector& v, const ProofOptions& options) {
  const char* where = "TPlane::compute_proofs(v)";
  check_tube(v, "velocity", where);
  if (eps_ == 0) throw Error(std::string(where) + ": no detections yet (call compute_detections first)");
  check_options(options, eps_, where);
  prove(LoopFunction(v), options);
}

void TPlane::compute_proofs(const TubeVector& p, const TubeVector& w, const ProofOptions& options) {
  const char* where = "TPlane::compute_proofs(p, w)";
  check_tube(p, "position", where);
  check_tube(w, "velocity", where);
  if (eps_ == 0) throw Error(std::string(where) + ": no detections yet (call compute_detections first)");
  check_options(options, eps_, where);
  prove(LoopFunction(p, w), options);
}

// Boxes on which N may be run for the loop l: the hull, then its inflation,
// each kept only if all its zeros would be zeros in l: strictly inside the
// square and above the diagonal, meeting no outer leaf but l's. The hull
// holds all of l's leaves, so a box meets another component iff more outer
// leaves than l's intersect it.
std::vector<IntervalVector> TPlane::newton_boxes(const Loop& l, double inflation) const {
  auto admissible = [&](const IntervalVector& b) {
    for (std::size_t i = 0; i < 2; ++i) {
      if (!(domain_[i].lb() < b[i].lb() && b[i].ub() < domain_[i].ub())) return false;
    }
    if (!(b[0].ub() < b[1].lb())) return false;
    std::size_t outer = 0;
    for (std::size_t k : paving_.leaves_intersecting(b)) outer += paving_.tag(k) != PavingTag::Outside;
    return outer == l.boxes_.size();
  };
  std::vector<IntervalVector> r;
  if (!admissible(l.t_box_)) return r;  // an inflated box would meet the same leaves
  r.push_back(l.t_box_);
  for (int k = 0; k < 4 && inflation > 0; ++k, inflation *= 2) {
    IntervalVector b = l.t_box_;
    for (std::size_t i = 0; i < 2; ++i) {
      const double d = inflation * b[i].rad();
      b[i] = Interval(b[i].lb() - d, b[i].ub() + d);  // any box holding the hull will do: no rounding care
    }
    if (!admissible(b)) break;  // nor would a larger one be
    r.push_back(b);
  }
  return r;
}

void TPlane::prove(const LoopFunction& f, const ProofOptions& options) {
  // Computed aside, then committed: an exception leaves the previous proofs whole.
  struct Proof {
    IntervalVector map_box;
    std::optional<int> degree;
    bool newton = false;
    std::optional<std::size_t> count;
    std::vector<IntervalVector> newton_boxes;
    std::vector<SplitPiece> pieces;
    std::optional<std::size_t> split_count;
  };
  std::vector<Proof> proofs(detections_.size());
  // Sequential part: map boxes, and the boxes where N may run.
  for (std::size_t i = 0; i < detections_.size(); ++i) {
    const Loop& l = detections_[i];
    proofs[i].map_box = f.position(l.t_box_[0]) | f.position(l.t_box_[1]);
    if (l.complete_ && options.newton) proofs[i].newton_boxes = newton_boxes(l, options.newton_inflation);
  }

  const PlaneJacobian jac = f.jacobian_function();
  DegreeOptions degree_options;
  degree_options.min_edge_length = options.degree_edge_fraction * eps_;
  degree_options.max_evaluations = options.degree_max_evaluations;
  CountOptions count_options;
  count_options.min_width = options.count_width_fraction * eps_;
  count_options.max_boxes = options.count_max_boxes;
  SplitOptions split_options;
  split_options.max_levels = options.split_max_levels;
  split_options.max_boxes = options.split_max_boxes;
  split_options.degree = degree_options;
  split_options.count = options.count;
  split_options.count_options = count_options;

  // One meter for all the components: the budget is that of the whole call.
  BudgetMeter meter(options.budget, "TPlane::compute_proofs");
  // Each task writes its own Proof only: the results do not depend on threads.
  tbb::parallel_for(std::size_t{0}, detections_.size(), [&](std::size_t i) {
    const Loop& l = detections_[i];
    Proof& p = proofs[i];
    if (!l.complete_) return;
    const PlaneFunction fn = f.memoized_function();  // one per task: it is not shared between threads
    p.degree = detail::topological_degree(l.boxes_, fn, degree_options, meter).degree;
    for (const IntervalVector& b : p.newton_boxes) {
      if ((p.newton = newton_test(b, fn, jac).proven)) break;
    }
    if (options.count && p.degree) {
      p.count = detail::count_zeros(l.boxes_, *p.degree, fn, jac, count_options, meter).count;
    }
    if (needs_split(p.degree, p.count, options)) {
      SplitResult split = detail::split_region(l.boxes_, fn, jac, split_options, meter, p.degree, l.inner_);
      p.split_count = split.count();
      p.pieces = std::move(split.pieces);
    }
  });

  for (std::size_t i = 0; i < detections_.size(); ++i) {
    Loop& l = detections_[i];
    l.map_box_ = std::move(proofs[i].map_box);
    l.degree_ = proofs[i].degree;
    l.proven_newton_ = proofs[i].newton;
    l.count_ = proofs[i].count ? proofs[i].count : proofs[i].split_count;
    l.pieces_.clear();
    for (SplitPiece& s : proofs[i].pieces) {
      Loop piece;
      piece.t_box_ = s.t_box;
      piece.map_box_ = f.position(s.t_box[0]) | f.position(s.t_box[1]);
      piece.boxes_ = std::move(s.boxes);
      piece.complete_ = true;
      piece.degree_ = s.degree;
      piece.count_ = s.count;
      l.pieces_.push_back(std::move(piece));
    }
  }
}

}  // namespace sillage
