#include "sillage/loops/orientation.h"

#include <cmath>
#include <cstddef>

namespace sillage::detail {

namespace {

constexpr double kUnit = 0x1p-53;                           // unit roundoff of binary64
constexpr double kFilterBound = (3.0 + 16.0 * kUnit) * kUnit;  // Shewchuk's ccwerrboundA

// a + b = s + e exactly (Knuth's TwoSum, valid in round-to-nearest without overflow).
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a, av = s - bv;
  e = (a - av) + (b - bv);
}

// Exact sum of the terms as a non-overlapping expansion (Shewchuk's
// Grow-Expansion, zeros dropped); components in increasing magnitude, so the
// last one carries the sign of the sum.
int expansion_sign(const double* terms, std::size_t n) {
  double h[16];
  std::size_t m = 0;
  for (std::size_t k = 0; k < n; ++k) {
    double q = terms[k];
    std::size_t out = 0;
    for (std::size_t i = 0; i < m; ++i) {
      double s = 0, e = 0;
      two_sum(q, h[i], s, e);
      q = s;
      if (e != 0) h[out++] = e;
    }
    if (q != 0) h[out++] = q;
    m = out;
  }
  if (m == 0) return 0;
  return h[m - 1] > 0 ? 1 : -1;
}

int exact_orientation(double ax, double ay, double bx, double by, double cx, double cy) {
  // ax by - ax cy + bx cy - bx ay + cx ay - cx by, each product split into
  // its rounded value and its exact rounding error.
  const double f[6][2] = {{ax, by}, {-ax, cy}, {bx, cy}, {-bx, ay}, {cx, ay}, {-cx, by}};
  double terms[12];
  for (std::size_t k = 0; k < 6; ++k) {
    const double p = f[k][0] * f[k][1];
    terms[2 * k] = p;
    terms[2 * k + 1] = std::fma(f[k][0], f[k][1], -p);
  }
  return expansion_sign(terms, 12);
}

}  // namespace

int orientation_sign(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (ax - cx) * (by - cy), right = (ay - cy) * (bx - cx);
  const double det = left - right;
  const double bound = kFilterBound * (std::fabs(left) + std::fabs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return exact_orientation(ax, ay, bx, by, cx, cy);
}

}  // namespace sillage::detail
