#include "sillage/loops/component_split.h"

#include <algorithm>
#include <string>

#include "sillage/error.h"
#include "sillage/loops/plane_evaluation.h"
#include "sillage/paving/component.h"

namespace sillage {

std::optional<int> SplitResult::degree() const {
  int d = 0;
  for (const SplitPiece& p : pieces) {
    if (!p.degree) return std::nullopt;
    d += *p.degree;
  }
  return d;
}

std::optional<std::size_t> SplitResult::count() const {
  std::size_t n = 0;
  for (const SplitPiece& p : pieces) {
    if (!p.count) return std::nullopt;
    n += *p.count;
  }
  return n;
}

std::size_t SplitResult::nb_proven() const {
  return static_cast<std::size_t>(
      std::count_if(pieces.begin(), pieces.end(), [](const SplitPiece& p) { return p.proves_zero(); }));
}

namespace {

// A part of the region still to settle, at some refinement level.
struct Pending {
  std::vector<IntervalVector> boxes;
  std::size_t level = 0;
  std::optional<int> degree;  // known from its parent when it is the parent minus zero-free boxes
};

class Splitter {
 public:
  Splitter(const PlaneFunction& f, const PlaneJacobian& jacobian, const SplitOptions& options, BudgetMeter& meter)
      : f_(f), jacobian_(jacobian), options_(options), meter_(meter) {}

  SplitResult run(const std::vector<IntervalVector>& boxes, const std::optional<int>& degree) {
    std::vector<Pending> work{{boxes, 0, degree}};
    while (!work.empty()) {
      Pending p = std::move(work.back());
      work.pop_back();
      std::vector<IntervalVector> kept = refine(p.boxes);
      const std::size_t level = p.level + 1;
      result_.nb_levels = std::max(result_.nb_levels, level);
      if (kept.empty()) continue;  // every half excludes 0: no zero there at all
      std::vector<Component> parts = connected_components(kept);
      const bool last = level >= options_.max_levels;
      for (Component& c : parts) {
        const bool small = 2 * c.boxes.size() <= options_.max_boxes;
        if (parts.size() == 1 && p.degree && !last && small) {
          // Same zeros as the parent, same degree, still unsettled: refine further.
          work.push_back({std::move(c.boxes), level, p.degree});
          continue;
        }
        // A single part with the parent's degree has the parent's zeros, which
        // could not be counted: the count is not tried again.
        const bool same = parts.size() == 1 && p.degree;
        SplitPiece piece = assess(std::move(c.boxes), c.hull, same ? p.degree : std::nullopt, !same);
        if (settled(piece) || last || !small) {
          result_.pieces.push_back(std::move(piece));
        } else {
          work.push_back({std::move(piece.boxes), level, piece.degree});
        }
      }
    }
    std::stable_sort(result_.pieces.begin(), result_.pieces.end(), [](const SplitPiece& a, const SplitPiece& b) {
      if (a.t_box[0].lb() != b.t_box[0].lb()) return a.t_box[0].lb() < b.t_box[0].lb();
      return a.t_box[1].lb() < b.t_box[1].lb();
    });
    return std::move(result_);
  }

 private:
  // Bisects every box once and keeps the halves where f* may vanish.
  std::vector<IntervalVector> refine(const std::vector<IntervalVector>& boxes) {
    std::vector<IntervalVector> kept;
    for (const IntervalVector& b : boxes) {
      if (options_.inside && options_.inside(b)) {
        kept.push_back(b);
        continue;
      }
      auto [lo, hi] = b.bisect();
      for (IntervalVector* h : {&lo, &hi}) {
        meter_.add();
        ++result_.nb_evaluations;
        const IntervalVector y = detail::eval_plane_function(f_, *h, "split_region");
        if (y[0].contains(0.0) && y[1].contains(0.0)) kept.push_back(std::move(*h));
      }
    }
    return kept;
  }

  SplitPiece assess(std::vector<IntervalVector> boxes, const IntervalVector& hull, std::optional<int> degree,
                    bool count) {
    SplitPiece piece;
    piece.boxes = std::move(boxes);
    piece.t_box = hull;
    piece.degree = degree ? degree : detail::topological_degree(piece.boxes, f_, options_.degree, meter_).degree;
    if (count && options_.count && piece.degree) {
      piece.count = detail::count_zeros(piece.boxes, *piece.degree, f_, jacobian_, options_.count_options, meter_).count;
    }
    return piece;
  }

  bool settled(const SplitPiece& p) const { return p.count || (!options_.count && p.proves_zero()); }

  const PlaneFunction& f_;
  const PlaneJacobian& jacobian_;
  const SplitOptions& options_;
  BudgetMeter& meter_;
  SplitResult result_;
};

}  // namespace

SplitResult split_region(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                         const PlaneJacobian& jacobian, const SplitOptions& options) {
  BudgetMeter meter(options.budget, "split_region");
  return detail::split_region(boxes, f, jacobian, options, meter, std::nullopt);
}

SplitResult detail::split_region(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                                 const PlaneJacobian& jacobian, const SplitOptions& options, BudgetMeter& meter,
                                 const std::optional<int>& degree) {
  if (boxes.empty()) throw Error("split_region: no box (the region is empty)");
  if (options.max_levels == 0 || options.max_boxes == 0) {
    throw Error("split_region: max_levels and max_boxes must be positive, got " +
                std::to_string(options.max_levels) + " and " + std::to_string(options.max_boxes));
  }
  for (const IntervalVector& b : boxes) detail::check_plane_box(b, "split_region");
  return Splitter(f, jacobian, options, meter).run(boxes, degree);
}

}  // namespace sillage
