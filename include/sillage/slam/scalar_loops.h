#pragma once
// Loops of a scalar configuration p (dimension 1): the existence test that
// lets C_{p⇒z} run with h the identity of a 1-D state, as in Borda's double
// weighing (thesis 7.1.3, (7.5): x(t1) = x(t2) ⇒ z(t1) = z(t2), the pointer z
// an unknown function of the mass x).
//
// The t-plane's existence test, the topological degree, is planar (ch. 6).
// For a scalar p the zeros of f(t1, t2) = p(t2) - p(t1) are curves, not
// points, and they reach the diagonal at every extremum of p: a detection is
// then never "complete". C_{p⇒z} needs less than the degree: a connected set
// of t-boxes lying strictly above the diagonal that surely holds a loop. If f
// is surely > 0 somewhere in such a set and surely < 0 elsewhere in it, the
// intermediate value theorem along a path between the two gives a zero of f
// in the set (f is continuous: p' = w is bounded); [f] on the faces of its
// boxes decides it (the faces next to a box outside the loop set carry its
// sign).
//
// The pieces tested: the detections of the t-plane with (7.28) on the
// embedding (p, 0), (w, 0) (the zero component is equal at every pair of
// times, so the loop set is p's), without the boxes that reach the
// diagonal, cut into columns of t1 one eps wide, and split into connected
// components. A proven piece pins p on its column to p on its band of t2
// (and back): every proven piece is a constraint of its own.
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// One piece of the loop set of a scalar p: its t-boxes (t1, t2), their hull, and whether it surely
// holds a loop p(t1) = p(t2) with t1 < t2.
struct ScalarLoop {
  std::vector<IntervalVector> boxes;                          // the t-boxes ([t1], [t2]), connected
  IntervalVector hull = IntervalVector(2, Interval::empty());  // their hull
  bool proven = false;                                        // the existence test holds
};

// "ScalarLoop(boxes=12, hull=..., proven=True)".
std::string repr(const ScalarLoop& l);

// The existence test: true when the t-boxes (t1, t2) are connected, lie strictly above the diagonal
// (t1 < t2 in each box) and [f] = [p]([t2]) - [p]([t1]) (∩ the integral of w) is surely positive on a face of one of
// them and surely negative on a face of another. p and w 1-D on one TDomain covering the boxes
// (DimensionError, Error otherwise).
bool scalar_loop_exists(const std::vector<IntervalVector>& boxes, const TubeVector& p, const TubeVector& w);

// The pieces of the loop set of the scalar p (see above) at precision eps > 0 (seconds), each with
// its existence test; chronological by t1. p and w 1-D on one TDomain (DimensionError, Error
// otherwise). Cancelled once `cancel` is (checked at every box of the t-plane and every piece).
std::vector<ScalarLoop> scalar_loops(double eps, const TubeVector& p, const TubeVector& w,
                                     const CancelToken& cancel = {});

}  // namespace sillage
