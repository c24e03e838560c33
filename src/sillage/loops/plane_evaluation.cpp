#include "sillage/loops/plane_evaluation.h"

#include <string>

#include "sillage/error.h"

namespace sillage::detail {

IntervalVector eval_plane_function(const PlaneFunction& f, const IntervalVector& box, const char* where) {
  IntervalVector y = f(box);
  if (y.size() != 2) {
    throw DimensionError(std::string(where) + ": the plane function returned " + std::to_string(y.size()) +
                         " components on " + box.str() + " (2 expected)");
  }
  if (y.is_empty() && !box.is_empty()) {
    throw Error(std::string(where) + ": the plane function returned an empty box on " + box.str() +
                " (an inclusion function never does)");
  }
  return y;
}

IntervalMatrix eval_plane_jacobian(const PlaneJacobian& jacobian, const IntervalVector& box, const char* where) {
  IntervalMatrix j = jacobian(box);
  if (j.rows() != 2 || j.cols() != 2) {
    throw DimensionError(std::string(where) + ": the Jacobian returned a " + std::to_string(j.rows()) + "x" +
                         std::to_string(j.cols()) + " matrix on " + box.str() + " (2x2 expected)");
  }
  if (j.is_empty() && !box.is_empty()) {
    throw Error(std::string(where) + ": the Jacobian returned an empty matrix on " + box.str() +
                " (an enclosure never does)");
  }
  return j;
}

Interval determinant2(const IntervalMatrix& a) { return a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0); }

void check_plane_box(const IntervalVector& box, const char* where) {
  if (box.size() != 2) {
    throw DimensionError(std::string(where) + ": a box of the plane must be 2-D, got " + box.str());
  }
  if (box.is_unbounded()) throw Error(std::string(where) + ": unbounded box " + box.str());
}

}  // namespace sillage::detail
