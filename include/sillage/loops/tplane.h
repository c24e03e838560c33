#pragma once
// TPlane: loops of a planar trajectory in the t-plane (thesis ch. 6).
//
// Detections (6.2, Alg. 6; loop_sivia.h): a paving of the t-plane
// [t0, tf]^2 approximating the set 𝕋 = {(t1, t2) | t1 < t2, 0 ∈ [f](t1, t2)}
// of the feasible loops, with (loop_function.h)
//   - from a velocity tube v (2-D): [f]([t1], [t2]) = ∫_{[t1]}^{[t2]} [v] (6.6);
//   - from a position tube p and its derivative w (both 2-D): the tighter
//     [f]([t1], [t2]) = ([p]([t2]) - [p]([t1])) ∩ ∫_{[t1]}^{[t2]} [w] (7.28).
// A t-box is Outside when t1 > t2 surely, or 0 ∉ [f] (6.8), or the
// injectivity test 0 ∉ [v]([t1^-, t2^+]) holds (6.9); it is Inner when
// t1 < t2 surely and ∫v^- <= 0 <= ∫v^+ on both components (6.10), from v
// only (with (p, w) the positions constrain the trajectories further, so the
// inner test of w alone would not be sound: there is no Inner leaf).
// Boxes are bisected down to width eps (in time units).
//
// The connected components Ω_i of the outer approximation are the
// detections, ordered by the lower corner of their hull (t1 first, then t2;
// ties in paving pre-order): chronologically by the first passage. A
// component is complete when it lies strictly inside the square and strictly
// above the diagonal t1 = t2. On the sides of the square the boundary of Ω_i
// is not known (6.3.3, footnote 5: loops may go on outside the observed
// time span); on the diagonal f(t, t) = 0 always, so a component reaching it
// has zeros of f on its boundary and its degree is undefined.
//
// Proofs (6.3), for each complete component: the degree test T
// (topological_degree.h, with boundary refinement), the interval Newton test
// N on the hull (zero_tests.h, only when the hull meets no other component:
// then a zero in the hull is a zero in Ω_i; see ProofOptions for an
// inflated retry), and the count of loops (Alg. 10, Remark 6.1). A
// component whose degree is 0 or undetermined, or whose loops are not
// counted, is then split into pieces with zero-free boundaries
// (component_split.h): each piece of non-zero degree proves a loop. Components are processed in parallel (oneTBB); results never
// depend on the number of threads.
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "sillage/budget.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/outcome.h"
#include "sillage/paving/paving.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class LoopFunction;

// One detection Ω_i and what is known of it.
class Loop {
 public:
  // Leaves of the outer approximation in this component (pre-order).
  const std::vector<IntervalVector>& boxes() const { return boxes_; }
  // Number of those leaves proven inside 𝕋 (Inner).
  std::size_t nb_inner() const { return nb_inner_; }
  // [t1] x [t2]: hull of the boxes.
  const IntervalVector& t_box() const { return t_box_; }
  // Hull of the positions p([t1]) ∪ p([t2]) (empty before compute_proofs).
  // From v alone, positions are relative to the start t0 of v's TDomain
  // (p(t) - p(t0) = ∫_{t0}^{t} v); with (p, w), the positions of p.
  const IntervalVector& map_box() const { return map_box_; }
  // Strictly inside the t-plane and above its diagonal (see TPlane).
  bool complete() const { return complete_; }
  // Degree of f over the component; nullopt if not computed or undetermined.
  std::optional<int> degree() const { return degree_; }
  bool proven() const { return degree_ && *degree_ != 0; }  // a loop, proven by T
  bool proven_newton() const { return proven_newton_; }    // a unique loop, proven by N
  // Exact number of loops in the component (Alg. 10), when the degree is
  // known and det [J_f] keeps its sign where loops may be. It may be 0: a
  // proof that this detection holds no loop.
  // When the split of Ω_i (component_split.h) counted every piece, the sum.
  std::optional<std::size_t> count() const { return count_; }
  // The pieces of Ω_i when it was split (empty otherwise): disjoint sub-loops,
  // each with its boxes, t-box, map box, degree and count (complete, never
  // split again, proven_newton false). Every loop of Ω_i lies in a piece.
  const std::vector<Loop>& pieces() const { return pieces_; }
  std::size_t nb_proven_pieces() const;  // pieces of non-zero degree
  // A loop is proven in Ω_i: by T on Ω_i itself or on one of its pieces.
  bool proven_split() const { return proven() || nb_proven_pieces() > 0; }

 private:
  friend class TPlane;
  std::vector<IntervalVector> boxes_;
  std::size_t nb_inner_ = 0;
  IntervalVector t_box_ = IntervalVector(2, Interval::empty());
  IntervalVector map_box_ = IntervalVector(2, Interval::empty());
  bool complete_ = false;
  std::optional<int> degree_;
  bool proven_newton_ = false;
  std::optional<std::size_t> count_;
  std::vector<Loop> pieces_;
  std::vector<bool> inner_;  // inner_[k]: boxes_[k] is an Inner leaf (for the split)
};

// Tuning of compute_proofs; the lengths are fractions of the eps of the
// detections (times in seconds).
struct ProofOptions {
  // Boundary edges of Ω_i are bisected for the degree down to this length.
  double degree_edge_fraction = 0.01;
  // Cap on the evaluations of [f] for one degree.
  std::size_t degree_max_evaluations = 1u << 20;
  // ζ of Remark 6.1: boxes are bisected for the Jacobian down to this width.
  double count_width_fraction = 0.1;
  // Cap on the refined boxes of one count.
  std::size_t count_max_boxes = 1u << 16;
  bool newton = true;  // run the Newton test N
  // When N fails on the hull, it is tried again on the hull widened on each
  // side by this fraction of its radius, then by 2, 4 and 8 times it
  // (ε-inflation: N([t]) ⊂ int([t]) is often out of reach on the hull, whose
  // size is that of the uncertainty on f, and within reach on a larger box),
  // as long as the box lies strictly inside the square, strictly above the
  // diagonal, and meets no other component. 0: the hull only.
  double newton_inflation = 0.25;
  bool count = true;   // run Alg. 10
  // Split the complete detections of degree 0 or undetermined, or not
  // counted, into pieces (component_split.h): up to split_max_levels
  // bisections of their boxes (3: down to eps/2.8, inside Ω_i only), at most
  // split_max_boxes boxes per piece being refined.
  bool split = true;
  // Bisections of the boxes of a piece still to settle (3: down to eps/2.8, inside the detection).
  std::size_t split_max_levels = 3;
  // Cap on the boxes of a piece being refined.
  std::size_t split_max_boxes = 1u << 15;
  // For the whole of compute_proofs: every evaluation of the degree test and
  // every box of the counts counts as a box (budget.h).
  Budget budget;
};

class TPlane {
 public:
  // The square tdomain^2: tdomain bounded with lb < ub (Error otherwise).
  explicit TPlane(const Interval& tdomain);
  // The square [t0, tf]^2 of a TDomain (Error if null).
  explicit TPlane(const std::shared_ptr<TDomain>& td);

  const IntervalVector& domain() const { return domain_; }  // [t0, tf]^2

  // Alg. 6 from a 2-D velocity tube whose TDomain covers [t0, tf]. Error if
  // eps <= 0 or NaN, DimensionError if v is not 2-D, Error if its TDomain
  // does not cover the t-plane. Replaces the previous results (kept
  // whole if it throws). The paving's nodes count against `budget`
  // (budget.h: BudgetExceeded, Cancelled).
  void compute_detections(double eps, const TubeVector& v, const Budget& budget = {});
  // Alg. 6 with the tighter function (7.28) from positions and velocities.
  void compute_detections(double eps, const TubeVector& p, const TubeVector& w, const Budget& budget = {});
  // The same two, keeping the detections so far instead of throwing when the
  // budget is spent or the run cancelled, and saying how it ended (outcome.h):
  //  - Converged: the detections of compute_detections;
  //  - Stopped / Cancelled: the t-boxes not yet classified are Boundary
  //    leaves of paving(), so the detections (its components, always
  //    computed, even once cancelled) still enclose every loop; they are
  //    coarser, and may reach the diagonal or merge (fewer complete ones);
  //  - NoSolution: every t-box is proven outside 𝕋: no detection, no loop.
  // The previous results are replaced in every case; errors are still thrown.
  Summary compute_detections_run(double eps, const TubeVector& v, const Budget& budget = {});
  Summary compute_detections_run(double eps, const TubeVector& p, const TubeVector& w, const Budget& budget = {});
  // Degree test, Newton test and loop count on each complete detection, and
  // the map box of every detection, with the inclusion function of v (or of
  // (p, w)): normally the tubes given to compute_detections. Any tubes
  // enclosing the same trajectory are sound. Error before compute_detections.
  // Replaces the previous proofs (kept whole if it throws).
  void compute_proofs(const TubeVector& v, const ProofOptions& options = {});
  // The same proofs from positions p and velocities w (7.28).
  void compute_proofs(const TubeVector& p, const TubeVector& w, const ProofOptions& options = {});

  double eps() const { return eps_; }          // of the last detections (0 before)
  const Paving& paving() const { return paving_; }  // the t-plane paving (6.8)-(6.10)
  std::size_t nb_detections() const { return detections_.size(); }  // complete or not
  // Number of detections strictly inside the square and above its diagonal.
  std::size_t nb_complete_detections() const;
  std::size_t nb_proofs() const;         // complete detections proven by T
  std::size_t nb_newton_proofs() const;  // ... proven a unique loop by N
  // The detections (Loop), ordered by the lower corner of their hull: chronologically by the first
  // passage.
  const std::vector<Loop>& detections() const { return detections_; }
  // Every proven sub-loop: for each detection, its pieces of non-zero
  // degree if it has some, else the detection itself if T proves it.
  std::vector<Loop> proofs() const;

 private:
  void check_tube(const TubeVector& x, const char* what, const char* where) const;
  // The loop function of the tubes, after checking them and eps (Error).
  LoopFunction checked_function(double eps, const TubeVector& v) const;
  LoopFunction checked_function(double eps, const TubeVector& p, const TubeVector& w) const;
  // keep_partial: the run form (above); else throws before replacing anything.
  Summary detect(double eps, const LoopFunction& f, const Budget& budget, bool keep_partial);
  void prove(const LoopFunction& f, const ProofOptions& options);
  std::vector<IntervalVector> newton_boxes(const Loop& l, double inflation) const;

  IntervalVector domain_;
  double eps_ = 0.0;
  Paving paving_;
  std::vector<Loop> detections_;
};

}  // namespace sillage
