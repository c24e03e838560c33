#include "sillage/loops/topological_degree.h"

#include <cmath>
#include <string>

#include "sillage/error.h"
#include "sillage/loops/plane_evaluation.h"

// Why the count below is the winding number (Theorem 6.1 made explicit).
//
// Tag a piece P (a closed segment of a loop) on which 0 ∉ [f](P) by a
// quarter q ∈ {0, 1, 2, 3}, Alg. 9's (c, s) read as a direction:
//   (1,+) -> 0, (2,+) -> 1, (1,-) -> 2, (2,-) -> 3.
// Then f*(P) lies in the open half-plane whose directions form the open arc
// A_q = (q π/2 - π/2, q π/2 + π/2) (mod 2π), a contractible arc.
//
// Consecutive pieces P, P' share an end point a, so f*(a) ∈ A_q ∩ A_q'. Hence
// q' - q ≠ 2 (mod 4): opposite half-planes do not meet. Write δ ∈ {-1, 0, 1}
// for q' - q taken in that range.
//
// Follow a continuous lift θ of the angle of f* along the loop. On P it stays
// in one lift (Φ - π/2, Φ + π/2) of A_q. At a, θ(a) is also in a lift of A_q';
// the lifts of A_q' are centred at Φ + δ π/2 + 2πm, and only m = 0 meets
// (Φ - π/2, Φ + π/2) (the others are at least 3π/2 away, more than the arc
// length π). So on P' the lift is centred at Φ' = Φ + δ π/2. After a full
// turn, at the start point a_1, the lift is centred at Φ_1 + Σδ π/2 and holds
// θ(a_1) + 2π W (W the winding number), while θ(a_1) ∈ (Φ_1 - π/2, Φ_1 + π/2).
// Σδ is a multiple of 4 (the tags come back to q_1), so Σδ π/2 is a multiple
// of 2π within distance < π of 2πW: W = Σδ / 4, for every f* enclosed by [f]
// and whatever admissible tag was chosen (Alg. 9 prefers coordinate 1).
//
// Alg. 8 counts +1 for each cyclic transition (1,+) -> (2,+) and -1 for each
// (2,+) -> (1,+): the net crossings of one boundary q = 0 | q = 1, which for a
// walk of ±1/0 steps from Q to Q + 4W is W as well. Its sign convention agrees
// with the mathematics: f = identity on a counter-clockwise square around 0
// gives the tags (2,-), (1,+), (2,+), (1,-) and the degree +1.
//
// The degree over Ω is the sum over its boundary loops: the loops of
// contour() form the boundary chain of the sum of the boxes (shared sides
// cancel), whatever the way they are linked at pinch points, and the degree is
// additive over the boxes.

namespace sillage {

namespace {

constexpr int kUnresolved = -1;

// Alg. 9: the quarter of the first coordinate of [f](P) with a constant sign.
int quarter_of(const IntervalVector& y) {
  if (y[0].lb() > 0) return 0;
  if (y[0].ub() < 0) return 2;
  if (y[1].lb() > 0) return 1;
  if (y[1].ub() < 0) return 3;
  return kUnresolved;
}

struct Piece {
  Point2 a, b;
  int quarter = kUnresolved;
};

IntervalVector segment_box(const Point2& a, const Point2& b) {
  return {Interval(std::min(a.x, b.x), std::max(a.x, b.x)), Interval(std::min(a.y, b.y), std::max(a.y, b.y))};
}

std::string point_text(const Point2& p) { return "(" + number_text(p.x) + ", " + number_text(p.y) + ")"; }

// Splits an axis-aligned segment at the middle of its varying coordinate;
// false when the floating-point grid leaves no point strictly inside.
bool split(const Point2& a, const Point2& b, Point2& m) {
  m = a;
  if (a.x != b.x) {
    m.x = Interval(std::min(a.x, b.x), std::max(a.x, b.x)).mid();
    return m.x != a.x && m.x != b.x;
  }
  m.y = Interval(std::min(a.y, b.y), std::max(a.y, b.y)).mid();
  return m.y != a.y && m.y != b.y;
}

void check_loops(const std::vector<ContourLoop>& loops, const DegreeOptions& options) {
  if (loops.empty()) throw Error("topological_degree: no boundary loop (the region is empty)");
  if (!(options.min_edge_length > 0) || !std::isfinite(options.min_edge_length)) {
    throw Error("topological_degree: min_edge_length must be positive and finite, got " +
                number_text(options.min_edge_length));
  }
  if (options.max_evaluations == 0) throw Error("topological_degree: max_evaluations must be positive");
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& edges = loops[l].edges;
    if (edges.empty()) throw Error("topological_degree: loop " + std::to_string(l) + " has no edge");
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const auto& e = edges[k];
      const std::string where = "topological_degree: loop " + std::to_string(l) + ", edge " + std::to_string(k);
      if (!std::isfinite(e.a.x) || !std::isfinite(e.a.y) || !std::isfinite(e.b.x) || !std::isfinite(e.b.y)) {
        throw Error(where + " has a non-finite end point");
      }
      if (e.a.x != e.b.x && e.a.y != e.b.y) {
        throw Error(where + " is not axis-aligned: " + point_text(e.a) + " -> " + point_text(e.b));
      }
      if (e.b != edges[(k + 1) % edges.size()].a) {
        throw Error(where + " ends at " + point_text(e.b) + " but the next edge starts at " +
                    point_text(edges[(k + 1) % edges.size()].a) + " (the loop is not closed)");
      }
    }
  }
}

// Covers the loops with pieces excluding 0, in loop order, refining each edge
// depth-first so that the pieces of a loop stay in their cyclic order.
class BoundaryCover {
 public:
  BoundaryCover(const PlaneFunction& f, const DegreeOptions& options, BudgetMeter& meter)
      : f_(f), options_(options), meter_(meter) {}

  std::vector<Piece> cover(const ContourLoop& loop) {
    std::vector<Piece> pieces;
    for (const auto& e : loop.edges) refine(e.a, e.b, pieces);
    return pieces;
  }

  std::size_t nb_evaluations() const { return nb_evaluations_; }

 private:
  void refine(const Point2& a, const Point2& b, std::vector<Piece>& pieces) {
    auto& stack = stack_;
    stack.assign(1, {a, b});
    while (!stack.empty()) {
      const auto [p, q] = stack.back();
      stack.pop_back();
      // Once the budget is spent, the pieces left are not evaluated: unresolved.
      int quarter = kUnresolved;
      if (nb_evaluations_ < options_.max_evaluations) {
        ++nb_evaluations_;
        meter_.add();
        quarter = quarter_of(detail::eval_plane_function(f_, segment_box(p, q), "topological_degree"));
      }
      Point2 m;
      const bool refinable = quarter == kUnresolved && nb_evaluations_ < options_.max_evaluations &&
                             std::abs(q.x - p.x) + std::abs(q.y - p.y) >= options_.min_edge_length && split(p, q, m);
      if (refinable) {
        stack.emplace_back(m, q);  // the first half on top: pieces come out in order
        stack.emplace_back(p, m);
      } else {
        pieces.push_back({p, q, quarter});
      }
    }
  }

  const PlaneFunction& f_;
  const DegreeOptions& options_;
  BudgetMeter& meter_;
  std::size_t nb_evaluations_ = 0;
  std::vector<std::pair<Point2, Point2>> stack_;  // pieces still to examine, reused across edges
};

// Σδ / 4 over the cyclic list of tags (see the proof above).
int winding_number(const std::vector<Piece>& pieces) {
  int quarter_turns = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Piece& next = pieces[(k + 1) % pieces.size()];
    const int step = (next.quarter - pieces[k].quarter + 4) % 4;
    if (step == 2) {
      throw Error("topological_degree: [f] has opposite signs on the two pieces sharing the point " +
                  point_text(pieces[k].b) + " (f is not an inclusion function)");
    }
    quarter_turns += step == 3 ? -1 : step;
  }
  return quarter_turns / 4;
}

}  // namespace

namespace {

DegreeResult degree_of(const std::vector<ContourLoop>& loops, const PlaneFunction& f, const DegreeOptions& options,
                       BudgetMeter& meter) {
  check_loops(loops, options);
  BoundaryCover cover(f, options, meter);
  DegreeResult result;
  int degree = 0;
  for (const auto& loop : loops) {
    const std::vector<Piece> pieces = cover.cover(loop);
    std::size_t unresolved = 0;
    for (const auto& p : pieces) unresolved += p.quarter == kUnresolved ? 1 : 0;
    result.nb_pieces += pieces.size();
    result.nb_unresolved += unresolved;
    if (unresolved == 0) degree += winding_number(pieces);
  }
  result.nb_evaluations = cover.nb_evaluations();
  if (result.nb_unresolved == 0) result.degree = degree;
  return result;
}

std::vector<ContourLoop> loops_of(const std::vector<IntervalVector>& boxes, const CancelToken& cancel) {
  if (boxes.empty()) throw Error("topological_degree: no box (the region is empty)");
  std::vector<ContourLoop> loops = contour(boxes, cancel);
  if (loops.empty()) throw Error("topological_degree: the boxes have no interior, the region has no boundary");
  return loops;
}

}  // namespace

DegreeResult topological_degree(const std::vector<ContourLoop>& loops, const PlaneFunction& f,
                                const DegreeOptions& options) {
  BudgetMeter meter(options.budget, "topological_degree");
  return degree_of(loops, f, options, meter);
}

DegreeResult topological_degree(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                                const DegreeOptions& options) {
  BudgetMeter meter(options.budget, "topological_degree");
  return degree_of(loops_of(boxes, meter.cancel()), f, options, meter);
}

DegreeRun topological_degree_run(const std::vector<ContourLoop>& loops, const PlaneFunction& f,
                                 const DegreeOptions& options) {
  BudgetMeter meter(options.budget, "topological_degree");
  return detail::run_metered<DegreeResult>(meter, [&] { return degree_of(loops, f, options, meter); });
}

DegreeRun topological_degree_run(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                                 const DegreeOptions& options) {
  BudgetMeter meter(options.budget, "topological_degree");
  return detail::run_metered<DegreeResult>(
      meter, [&] { return degree_of(loops_of(boxes, meter.cancel()), f, options, meter); });
}

DegreeResult detail::topological_degree(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                                        const DegreeOptions& options, BudgetMeter& meter) {
  return degree_of(loops_of(boxes, meter.cancel()), f, options, meter);
}

}  // namespace sillage
