#pragma once
// Elementary functions on intervals, set-based (IEEE 1788): each returns an
// interval containing the exact image of the part of x inside the function's
// domain (empty if none). Bounds come from libm results widened by a proven
// error bound; monotone pieces are evaluated at the right end points and the
// periodic functions use a rigorous enclosure of pi.
#include "sillage/interval/interval.h"

namespace sillage {

// Exponential.
Interval exp(const Interval& x);
Interval log(const Interval& x);          // natural logarithm on (0, inf)
Interval pow(const Interval& x, int n);   // x^n, n any integer (x^0 = [1,1])
Interval pow(const Interval& x, const Interval& y);  // exp(y log x), x > 0 (and 0^y = 0 for y > 0)
Interval pow(const Interval& x, double y);           // pow(x, int(y)) if y is an integer, else pow(x, [y, y])
// x^n for an integer n beyond the int range, known to lie in [n] (one sign)
// and to be odd or even (a Python int of any size).
Interval pow_big_int(const Interval& x, const Interval& n, bool odd);
Interval root(const Interval& x, int n);  // the real n-th root (odd n: all reals)
// Sine.
Interval sin(const Interval& x);
// Cosine.
Interval cos(const Interval& x);
// Tangent (the real line when x meets a pole).
Interval tan(const Interval& x);
// Arcsine, on the part of x in [-1, 1].
Interval asin(const Interval& x);
// Arccosine, on the part of x in [-1, 1].
Interval acos(const Interval& x);
// Arctangent.
Interval atan(const Interval& x);
Interval atan2(const Interval& y, const Interval& x);  // y first; range [-pi, pi]
// Hyperbolic sine.
Interval sinh(const Interval& x);
// Hyperbolic cosine.
Interval cosh(const Interval& x);
// Hyperbolic tangent.
Interval tanh(const Interval& x);

}  // namespace sillage
