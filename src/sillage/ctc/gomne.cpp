#include "sillage/ctc/gomne.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "sillage/ctc/ctc_qinter.h"
#include "sillage/ctc/shrink.h"

namespace sillage {

namespace {

void check_gomne_input(const std::vector<CtcPtr>& ctcs, const IntervalVector& box, const GomneOptions& o) {
  if (ctcs.empty()) throw Error("gomne: needs at least one contractor");
  for (std::size_t i = 0; i < ctcs.size(); ++i) {
    if (!ctcs[i]) throw Error("gomne: contractor " + std::to_string(i) + " is null");
    if (ctcs[i]->nb_vars() != box.size()) {
      throw DimensionError("gomne: contractor " + std::to_string(i) + " (" + ctcs[i]->name() + ") acts on " +
                           std::to_string(ctcs[i]->nb_vars()) + " variables, the box has " +
                           std::to_string(box.size()));
    }
  }
  if (!(o.eps > 0)) throw Error("gomne: eps must be > 0, got " + number_text(o.eps));
  if (o.q_max < 0) throw Error("gomne: q_max must be >= 0, got " + std::to_string(o.q_max));
  check_ratio(o.ratio, "gomne");
  if (std::isfinite(o.eps) && box.is_unbounded()) {
    throw Error("gomne: a finite eps (bisection) needs a bounded box, got " + box.str());
  }
}

// The non-empty leaves of the paving of S_q: each box is contracted by the
// fixed point of CtcQInter, dropped when empty, bisected while wider than eps.
std::vector<IntervalVector> pave(const Ctc& ctc, const IntervalVector& x0, double eps) {
  std::vector<IntervalVector> leaves, stack{x0};
  while (!stack.empty()) {
    IntervalVector x = std::move(stack.back());
    stack.pop_back();
    ctc.contract(x);
    if (x.is_empty()) continue;
    if (!(x.max_diam() > eps)) {
      leaves.push_back(std::move(x));
      continue;
    }
    auto halves = x.bisect();
    stack.push_back(std::move(halves.second));
    stack.push_back(std::move(halves.first));
  }
  return leaves;
}

// Measurement i is a proven outlier when its contractor empties every leaf.
std::vector<std::size_t> proven_outliers(const std::vector<CtcPtr>& ctcs, const std::vector<IntervalVector>& leaves) {
  std::vector<std::size_t> out;
  if (leaves.empty()) return out;
  for (std::size_t i = 0; i < ctcs.size(); ++i) {
    const bool violated_everywhere = std::all_of(leaves.begin(), leaves.end(), [&](const IntervalVector& leaf) {
      IntervalVector y(leaf);
      ctcs[i]->contract(y);
      return y.is_empty();
    });
    if (violated_everywhere) out.push_back(i);
  }
  return out;
}

}  // namespace

GomneResult gomne(const std::vector<CtcPtr>& ctcs, const IntervalVector& box, const GomneOptions& options) {
  check_gomne_input(ctcs, box, options);
  const int m = static_cast<int>(ctcs.size());
  const int q_max = std::min(options.q_max, m);
  GomneResult r;
  for (r.q = 0; r.q <= q_max; ++r.q) {
    if (r.q == m) {  // S_m = [x0]: nothing to contract
      if (!box.is_empty()) r.leaves = {box};
    } else {
      const CtcFixPoint ctc(std::make_shared<CtcQInter>(ctcs, r.q), options.ratio);
      r.leaves = pave(ctc, box, options.eps);
    }
    if (!r.leaves.empty()) break;
  }
  r.box = IntervalVector::empty(box.size());
  for (const auto& leaf : r.leaves) r.box |= leaf;
  r.outliers = proven_outliers(ctcs, r.leaves);
  return r;
}

}  // namespace sillage
