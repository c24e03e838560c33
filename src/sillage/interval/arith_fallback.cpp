// The interval kernels over rounding.h's scalar functions: exact for every
// operand, with branches on the rounding error; called only for the rare
// operands of the branch-free software path (tiny or huge magnitudes).
#include "sillage/interval/arith_kernels.h"

namespace sillage::detail {

BoundPair mul_bounds_scalar(double a, double b, double c, double d) { return mul_bounds<ScalarRounding>(a, b, c, d); }
BoundPair div_bounds_scalar(double a, double b, double c, double d) { return div_bounds<ScalarRounding>(a, b, c, d); }
BoundPair sqr_bounds_scalar(double a, double b) { return sqr_bounds<ScalarRounding>(a, b); }
BoundPair sqrt_bounds_scalar(double a, double b) { return sqrt_bounds<ScalarRounding>(a, b); }

}  // namespace sillage::detail
