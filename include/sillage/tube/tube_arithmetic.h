#pragma once
// Arithmetic and elementary functions on tubes, slice- and gate-wise
// (thesis (3.5)-(3.6)): for a trajectory x in [x] and y in [y], x(t) op y(t)
// lies in ([x] op [y])(t) for every t, since slice k of the result is
// [x](k) op [y](k) and gate k is [x](t_k) op [y](t_k), all with outward
// rounding. Binary operations need both tubes on the same TDomain
// (DimensionError otherwise); a double converts to a degenerate Interval.
#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"

namespace sillage {

Tube operator-(const Tube& x);

Tube operator+(const Tube& x, const Tube& y);
Tube operator-(const Tube& x, const Tube& y);
Tube operator*(const Tube& x, const Tube& y);
Tube operator/(const Tube& x, const Tube& y);

Tube operator+(const Tube& x, const Interval& y);
Tube operator-(const Tube& x, const Interval& y);
Tube operator*(const Tube& x, const Interval& y);
Tube operator/(const Tube& x, const Interval& y);

Tube operator+(const Interval& x, const Tube& y);
Tube operator-(const Interval& x, const Tube& y);
Tube operator*(const Interval& x, const Tube& y);
Tube operator/(const Interval& x, const Tube& y);

// Intersection and hull of two tubes (see Tube::operator&= / |=).
Tube operator&(const Tube& x, const Tube& y);
Tube operator|(const Tube& x, const Tube& y);

Tube sqr(const Tube& x);
Tube sqrt(const Tube& x);
Tube abs(const Tube& x);
Tube sign(const Tube& x);
Tube exp(const Tube& x);
Tube log(const Tube& x);
Tube pow(const Tube& x, int n);
Tube pow(const Tube& x, double p);
Tube pow(const Tube& x, const Interval& p);
Tube pow(const Tube& x, const Tube& p);
Tube root(const Tube& x, int n);
Tube sin(const Tube& x);
Tube cos(const Tube& x);
Tube tan(const Tube& x);
Tube asin(const Tube& x);
Tube acos(const Tube& x);
Tube atan(const Tube& x);
Tube sinh(const Tube& x);
Tube cosh(const Tube& x);
Tube tanh(const Tube& x);
Tube atan2(const Tube& y, const Tube& x);  // y first, like atan2(Interval, Interval)
Tube atan2(const Tube& y, const Interval& x);
Tube atan2(const Interval& y, const Tube& x);
Tube min(const Tube& x, const Tube& y);
Tube max(const Tube& x, const Tube& y);

}  // namespace sillage
