#pragma once
// Angles known modulo 2π. An interval [x] holding an angle stands for the
// arc x + 2πℤ: the true angle θ is in it when θ + 2kπ ∈ [x] for some
// integer k. Any representative will do, and a representative 2π wide or
// wider is the whole circle. Heading tubes declared as angles hold their
// slices and gates this way (dynamics/ctc_deriv_angle.h, ctc_eval_angle.h),
// so that a bearing can narrow a heading that dead reckoning let grow past
// 2π: the set of unwrapped headings is then many narrow arcs, whose hull as
// one real interval would keep nothing.
//
// Every result is a subset of the interval it narrows (contractors built on
// it only shrink) and keeps every angle of both arcs' intersection, rounding
// included (2π is enclosed rigorously).
#include "sillage/interval/interval.h"

namespace sillage {

// The part of [x] that meets the arc [y] + 2πℤ: the smallest
// representative inside [x] of the angles both hold. When a whole copy
// y + 2kπ fits in [x], it is that copy (the one nearest the middle of [x]);
// otherwise the hull of the pieces (y + 2kπ) ∩ [x]. Empty when the arcs are
// disjoint; [x] itself when [y] is the whole circle.
Interval angle_meet(const Interval& x, const Interval& y);

// The real values of [within] that lie on the arc [y] + 2πℤ: the hull of
// every piece (y + 2kπ) ∩ [within]. Unlike angle_meet, [within] is a set of
// real numbers (a lifted heading, the value of atan2), not an angle: every
// copy of y it holds is kept. [within] itself when [y] is the whole circle or
// [within] is unbounded.
Interval angle_lift(const Interval& y, const Interval& within);

// Whether the angle a (a double, any turn) lies on the arc [x] + 2πℤ,
// rounding included (a true angle is never reported outside).
bool angle_contains(const Interval& x, double a);

// Whether [x] is the whole circle (2π wide or wider, or unbounded).
bool angle_is_circle(const Interval& x);

}  // namespace sillage
