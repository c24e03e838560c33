#pragma once
// Exact sign of the planar orientation determinant
//   orient(a, b, c) = (b - a) x (c - a) = (bx - ax)(cy - ay) - (by - ay)(cx - ax):
// +1 when a, b, c turn counter-clockwise, -1 clockwise, 0 collinear.
//
// A floating-point evaluation is trusted when it exceeds its proven rounding
// error bound (Shewchuk's orient2d filter, (3 + 16u)u times the sum of the
// magnitudes of the two products, u = 2^-53); otherwise the six products of
// the expanded form are split exactly by fma (TwoProduct) and summed exactly
// as a floating-point expansion (TwoSum), whose leading term gives the sign.
// Exact when no product overflows and every non-zero coordinate has a
// magnitude >= 2^-480 (the products' rounding errors are then representable).
namespace sillage::detail {

int orientation_sign(double ax, double ay, double bx, double by, double cx, double cy);

}  // namespace sillage::detail
