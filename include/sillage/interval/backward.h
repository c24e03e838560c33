#pragma once
// Backward (inverse) projections: the building blocks of forward-backward
// contraction (HC4). For a constraint y = f(x1, ..., xk), bwd_f(y, x1, ..., xk)
// contracts each xi to (a hull enclosing) { xi in [xi] : exists the other
// xj in [xj] with f(x1, ..., xk) in [y] }. They only shrink their arguments and
// never remove a solution; an argument that has no solution becomes empty.
// Each returns false when it emptied an argument.
#include "sillage/interval/interval.h"

namespace sillage {

bool bwd_add(const Interval& y, Interval& x1, Interval& x2);   // y = x1 + x2
bool bwd_sub(const Interval& y, Interval& x1, Interval& x2);   // y = x1 - x2
bool bwd_mul(const Interval& y, Interval& x1, Interval& x2);   // y = x1 * x2
bool bwd_div(const Interval& y, Interval& x1, Interval& x2);   // y = x1 / x2
bool bwd_neg(const Interval& y, Interval& x);                  // y = -x
bool bwd_sqr(const Interval& y, Interval& x);                  // y = x^2
bool bwd_sqrt(const Interval& y, Interval& x);                 // y = sqrt(x)
bool bwd_pow(const Interval& y, Interval& x, int n);           // y = x^n
bool bwd_pow(const Interval& y, Interval& x, Interval& p);     // y = x^p (real exponent)
bool bwd_root(const Interval& y, Interval& x, int n);          // y = root(x, n)
bool bwd_exp(const Interval& y, Interval& x);
bool bwd_log(const Interval& y, Interval& x);
bool bwd_sin(const Interval& y, Interval& x);
bool bwd_cos(const Interval& y, Interval& x);
bool bwd_tan(const Interval& y, Interval& x);
bool bwd_asin(const Interval& y, Interval& x);
bool bwd_acos(const Interval& y, Interval& x);
bool bwd_atan(const Interval& y, Interval& x);
bool bwd_atan2(const Interval& theta, Interval& y, Interval& x);  // theta = atan2(y, x)
bool bwd_sinh(const Interval& y, Interval& x);
bool bwd_cosh(const Interval& y, Interval& x);
bool bwd_tanh(const Interval& y, Interval& x);
bool bwd_abs(const Interval& y, Interval& x);
bool bwd_min(const Interval& y, Interval& x1, Interval& x2);
bool bwd_max(const Interval& y, Interval& x1, Interval& x2);
bool bwd_sign(const Interval& y, Interval& x);

}  // namespace sillage
