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
  std::vector<bool> whole;  // whole[k]: boxes[k] is not bisected (inside the feasible set, or 0 deep in [f])
  std::size_t level = 0;
  std::optional<int> degree;  // known from its parent when it is the parent minus zero-free boxes
};

class Splitter {
 public:
  Splitter(const PlaneFunction& f, const PlaneJacobian& jacobian, const SplitOptions& options, BudgetMeter& meter)
      : f_(f), jacobian_(jacobian), options_(options), meter_(meter) {}

  SplitResult run(const std::vector<IntervalVector>& boxes, const std::optional<int>& degree,
                  std::vector<bool> whole) {
    if (whole.empty()) {  // not given: ask options.inside, if any
      whole.assign(boxes.size(), false);
      for (std::size_t k = 0; k < boxes.size() && options_.inside; ++k) whole[k] = options_.inside(boxes[k]);
    }
    std::vector<Pending> work{{boxes, std::move(whole), 0, degree}};
    while (!work.empty()) {
      Pending p = std::move(work.back());
      work.pop_back();
      auto [kept, kept_whole] = refine(p.boxes, p.whole);
      const std::size_t level = p.level + 1;
      result_.nb_levels = std::max(result_.nb_levels, level);
      if (kept.empty()) continue;  // every half excludes 0: no zero there at all
      // The tags carry the flags through connected_components.
      std::vector<PavingTag> tags(kept.size());
      for (std::size_t k = 0; k < kept.size(); ++k) tags[k] = kept_whole[k] ? PavingTag::Inner : PavingTag::Boundary;
      std::vector<Component> parts = connected_components(kept, tags);
      const bool last = level >= options_.max_levels;
      for (Component& c : parts) {
        const bool small = 2 * c.boxes.size() <= options_.max_boxes;
        if (parts.size() == 1 && p.degree && !last && small) {
          // Same zeros as the parent, same degree, still unsettled: refine further.
          work.push_back({std::move(c.boxes), flags_of(c), level, p.degree});
          continue;
        }
        // A single part with the parent's degree has the parent's zeros, which
        // could not be counted: the count is not tried again.
        const bool same = parts.size() == 1 && p.degree;
        std::vector<bool> flags = flags_of(c);
        SplitPiece piece = assess(std::move(c.boxes), c.hull, same ? p.degree : std::nullopt, !same);
        if (settled(piece) || last || !small) {
          result_.pieces.push_back(std::move(piece));
        } else {
          work.push_back({std::move(piece.boxes), std::move(flags), level, piece.degree});
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
  static std::vector<bool> flags_of(const Component& c) {
    std::vector<bool> r(c.tags.size());
    for (std::size_t k = 0; k < r.size(); ++k) r[k] = c.tags[k] == PavingTag::Inner;
    return r;
  }

  // Bisects every box once, but those proven inside (their halves are
  // inside too: no cut can cross them), and keeps the halves where f* may vanish.
  std::pair<std::vector<IntervalVector>, std::vector<bool>> refine(const std::vector<IntervalVector>& boxes,
                                                                   const std::vector<bool>& whole) {
    std::vector<IntervalVector> kept;
    std::vector<bool> kept_whole;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      if (whole[k]) {
        kept.push_back(boxes[k]);
        kept_whole.push_back(true);
        continue;
      }
      auto [lo, hi] = boxes[k].bisect();
      for (IntervalVector* h : {&lo, &hi}) {
        meter_.add();
        ++result_.nb_evaluations;
        const IntervalVector y = detail::eval_plane_function(f_, *h, "split_region");
        if (y[0].contains(0.0) && y[1].contains(0.0)) {
          kept.push_back(std::move(*h));
          kept_whole.push_back(deep(y));
        }
      }
    }
    return {std::move(kept), std::move(kept_whole)};
  }

  // 0 lies deep inside [f] on both components (farther than deep_margin of
  // its width from either bound): the halves of such a box would keep 0 as
  // well, so bisecting it further would not cut anything (a heuristic on the
  // cost only: a box kept whole just stays in its piece).
  bool deep(const IntervalVector& y) const {
    if (!(options_.deep_margin > 0)) return false;
    for (std::size_t i = 0; i < 2; ++i) {
      const double m = options_.deep_margin * (y[i].ub() - y[i].lb());
      if (!(-y[i].lb() > m && y[i].ub() > m)) return false;
    }
    return true;
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

SplitRun split_region_run(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                          const PlaneJacobian& jacobian, const SplitOptions& options) {
  BudgetMeter meter(options.budget, "split_region");
  return detail::run_metered<SplitResult>(
      meter, [&] { return detail::split_region(boxes, f, jacobian, options, meter, std::nullopt); });
}

SplitResult detail::split_region(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                                 const PlaneJacobian& jacobian, const SplitOptions& options, BudgetMeter& meter,
                                 const std::optional<int>& degree, const std::vector<bool>& inside) {
  if (boxes.empty()) throw Error("split_region: no box (the region is empty)");
  if (options.max_levels == 0 || options.max_boxes == 0) {
    throw Error("split_region: max_levels and max_boxes must be positive, got " +
                std::to_string(options.max_levels) + " and " + std::to_string(options.max_boxes));
  }
  for (const IntervalVector& b : boxes) detail::check_plane_box(b, "split_region");
  if (!inside.empty()) check_same_size(inside.size(), boxes.size(), "split_region (inside flags vs boxes)");
  return Splitter(f, jacobian, options, meter).run(boxes, degree, inside);
}

}  // namespace sillage
