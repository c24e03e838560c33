#include "sillage/slam/scalar_loops.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "sillage/error.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/tplane.h"
#include "sillage/paving/component.h"

namespace sillage {

namespace {

void check(const TubeVector& p, const TubeVector& w, const char* where) {
  if (p.size() != 1 || w.size() != 1) {
    throw DimensionError(std::string(where) + ": p and w must be 1-D (they have " + std::to_string(p.size()) +
                         " and " + std::to_string(w.size()) + " components)");
  }
  if (p.tdomain() != w.tdomain()) throw Error(std::string(where) + ": p and w must share one TDomain");
}

// (x, 0): a second component equal at every pair of times, so that the planar
// loop machinery sees exactly the loops of x.
TubeVector planar(const TubeVector& x) {
  return TubeVector(std::vector<Tube>{x[0], Tube(x.tdomain(), Interval(0.0))});
}

bool above_diagonal(const IntervalVector& t) { return t[0].ub() < t[1].lb(); }

// The test on connected boxes strictly above the diagonal, with f the planar
// loop function of the embedding (its first component is p(t2) - p(t1)).
bool sign_change(const std::vector<IntervalVector>& boxes, const LoopFunction& f) {
  bool positive = false, negative = false;
  for (const IntervalVector& b : boxes) {
    for (std::size_t side = 0; side < 4; ++side) {
      IntervalVector face = b;
      const std::size_t i = side / 2;
      face[i] = Interval(side % 2 == 0 ? b[i].lb() : b[i].ub());
      const Interval v = f(face)[0];
      if (v.is_empty()) continue;  // no trajectory there: says nothing
      positive = positive || v.lb() > 0.0;
      negative = negative || v.ub() < 0.0;
      if (positive && negative) return true;
    }
  }
  return false;
}

}  // namespace

std::string repr(const ScalarLoop& l) {
  return "ScalarLoop(boxes=" + std::to_string(l.boxes.size()) + ", hull=" + l.hull.str() +
         ", proven=" + (l.proven ? "True" : "False") + ")";
}

bool scalar_loop_exists(const std::vector<IntervalVector>& boxes, const TubeVector& p, const TubeVector& w) {
  check(p, w, "scalar_loop_exists(boxes, p, w)");
  for (const IntervalVector& b : boxes) {
    if (b.size() != 2) throw DimensionError("scalar_loop_exists(boxes, p, w): a t-box has " + std::to_string(b.size()) + " components, not 2");
    if (!b.is_subset(IntervalVector(2, p.tdomain()->t0_tf()))) {
      throw Error("scalar_loop_exists(boxes, p, w): the t-box " + b.str() + " leaves the TDomain " +
                  p.tdomain()->t0_tf().str());
    }
  }
  if (boxes.empty() || !std::all_of(boxes.begin(), boxes.end(), above_diagonal)) return false;
  if (connected_components(boxes).size() != 1) return false;
  const TubeVector p2 = planar(p), w2 = planar(w);
  return sign_change(boxes, LoopFunction(p2, w2));
}

std::vector<ScalarLoop> scalar_loops(double eps, const TubeVector& p, const TubeVector& w, const CancelToken& cancel) {
  check(p, w, "scalar_loops(eps, p, w)");
  if (!(eps > 0.0) || std::isinf(eps)) throw Error("scalar_loops(eps, p, w): eps must be positive and finite, not " + number_text(eps));
  if (p.is_empty() || w.is_empty()) return {};
  const TubeVector p2 = planar(p), w2 = planar(w);
  TPlane tp(p.tdomain());
  Budget budget;  // the caller's token alone
  budget.cancel = cancel;
  tp.compute_detections(eps, p2, w2, budget);
  // Columns of t1, eps wide, of the boxes strictly above the diagonal.
  const double t0 = p.tdomain()->t0();
  std::map<long, std::vector<IntervalVector>> columns;
  for (const Loop& d : tp.detections()) {
    for (const IntervalVector& b : d.boxes()) {
      if (above_diagonal(b)) columns[std::lround(std::floor((b[0].mid() - t0) / eps))].push_back(b);
    }
  }
  const LoopFunction f(p2, w2);
  std::vector<ScalarLoop> out;
  for (const auto& [column, boxes] : columns) {
    for (Component& c : connected_components(boxes)) {
      check_cancel(cancel, "scalar_loops");
      ScalarLoop l;
      l.hull = c.hull;
      l.boxes = std::move(c.boxes);
      l.proven = sign_change(l.boxes, f);
      out.push_back(std::move(l));
    }
  }
  return out;
}

}  // namespace sillage
