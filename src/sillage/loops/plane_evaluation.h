#pragma once
// Checked evaluations of the callables of plane_function.h, shared by the
// zero tests of this folder: a result of the wrong shape, or an empty result
// on a non-empty box, breaks the inclusion contract and throws Error naming
// the caller; the 2x2 interval determinant used by Newton and the count.
#include "sillage/loops/plane_function.h"

namespace sillage::detail {

// [f](box), checked to be a non-empty 2-D box. `where` names the caller.
IntervalVector eval_plane_function(const PlaneFunction& f, const IntervalVector& box, const char* where);
// [J](box), checked to be a non-empty 2x2 matrix.
IntervalMatrix eval_plane_jacobian(const PlaneJacobian& jacobian, const IntervalVector& box, const char* where);
// a00 a11 - a01 a10, outward rounded: contains det(A) for every real A in `a`.
Interval determinant2(const IntervalMatrix& a);
// Throws DimensionError unless `box` is 2-D, Error unless it is bounded.
void check_plane_box(const IntervalVector& box, const char* where);

}  // namespace sillage::detail
