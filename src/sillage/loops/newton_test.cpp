#include <cmath>
#include <optional>

#include "sillage/loops/plane_evaluation.h"
#include "sillage/loops/zero_tests.h"

// Why N([t]) encloses the zeros, and proves one when N([t]) ⊂ int([t]).
//
// For f* C^1 with J_f*(t) ∈ [J]([t]) on the box and x ∈ [t], the mean value
// matrix S(x) = ∫_0^1 J_f*(m + s (x - m)) ds lies in [J]([t]) (an interval
// matrix is convex) and f*(x) = f*(m) + S(x) (x - m), with f*(m) ∈ [f]({m}).
// When every real matrix of [J]([t]) is regular, a zero x of f* in [t] is
// x = m - S(x)^{-1} f*(m) ∈ N([t]), any enclosure of
// {m - A^{-1} y | A ∈ [J]([t]), y ∈ [f]({m})}: so [t] ∩ N([t]) keeps every
// zero, and N([t]) = ∅ proves there is none. If N([t]) ⊂ int([t]), the map
// x -> m - S(x)^{-1} f*(m) is continuous from [t] into [t]: by Brouwer it has a
// fixed point, a zero of f*; two zeros x, x' would give S (x - x') = 0 with S
// the regular mean value matrix between them, so the zero is unique in [t].
//
// The enclosure: Cramer's rule on the 2x2 system, once as is and once
// preconditioned by C ≈ mid([J])^{-1} (A x = y implies (C A) x = C y and
// C [J] ∋ C A, C [f](m) ∋ C y, so the preconditioned system encloses the same
// solutions; C is any real matrix, rounding of C costs nothing). When
// 0 ∉ det(C [J]) every C A is regular, hence every A, and the interval
// evaluation of Cramer's formulas encloses every solution. The preconditioned
// matrix is near the identity, which removes most of the dependency between
// the determinant and the numerators; the plain one keeps a chance when mid([J])
// is singular. Both being enclosures, their intersection is one too.

namespace sillage {

namespace {

// Cramer enclosure of {A^{-1} y | A ∈ a, y ∈ y}; nullopt if 0 ∈ det(a).
std::optional<IntervalVector> cramer(const IntervalMatrix& a, const IntervalVector& y) {
  const Interval det = detail::determinant2(a);
  if (det.contains(0.0)) return std::nullopt;
  return IntervalVector{(a(1, 1) * y[0] - a(0, 1) * y[1]) / det, (a(0, 0) * y[1] - a(1, 0) * y[0]) / det};
}

// An approximate inverse of mid(a), or nullopt when mid(a) is (numerically) singular.
std::optional<IntervalMatrix> preconditioner(const IntervalMatrix& a) {
  const Matrix m = a.mid();
  const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  if (det == 0 || !std::isfinite(det)) return std::nullopt;
  const Matrix c{{m[1][1] / det, -m[0][1] / det}, {-m[1][0] / det, m[0][0] / det}};
  for (const auto& row : c) {
    for (double x : row) {
      if (!std::isfinite(x)) return std::nullopt;
    }
  }
  return IntervalMatrix::from_point(c);
}

// N([t]), or nullopt when the Jacobian enclosure may be singular.
std::optional<IntervalVector> newton_operator(const IntervalVector& t, const PlaneFunction& f,
                                              const PlaneJacobian& jacobian) {
  const Vector m = t.mid();
  const IntervalVector fm = detail::eval_plane_function(f, IntervalVector::from_point(m), "newton_test");
  const IntervalMatrix j = detail::eval_plane_jacobian(jacobian, t, "newton_test");
  std::optional<IntervalVector> step = cramer(j, fm);
  if (auto c = preconditioner(j)) {
    if (auto s = cramer(*c * j, *c * fm)) step = step ? (*step & *s) : *s;
  }
  if (!step) return std::nullopt;
  return IntervalVector::from_point(m) - *step;
}

}  // namespace

NewtonResult newton_test(const IntervalVector& box, const PlaneFunction& f, const PlaneJacobian& jacobian,
                         const NewtonOptions& options) {
  detail::check_plane_box(box, "newton_test");
  NewtonResult result;
  result.box = box;
  // Once proven, the contraction goes on: it keeps the zero and tightens the box.
  while (!result.box.is_empty() && result.nb_iterations < options.max_iterations) {
    ++result.nb_iterations;
    const std::optional<IntervalVector> n = newton_operator(result.box, f, jacobian);
    if (!n) break;  // 0 ∈ det [J]: neither contraction nor proof
    if (!result.proven && n->is_interior_subset(result.box) && !n->is_empty()) result.proven = true;
    const IntervalVector next = result.box & *n;
    if (next.is_empty()) {  // no zero at all (impossible once proven, for a true enclosure)
      result.box = IntervalVector::empty(2);
      result.proven = false;
      break;
    }
    if (next == result.box) break;  // a fixed point of the contraction
    result.box = next;
  }
  return result;
}

}  // namespace sillage
