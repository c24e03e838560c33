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
// sqrt of a tube, slice- and gate-wise (rigorous).
Tube sqrt(const Tube& x);
// abs of a tube, slice- and gate-wise (rigorous).
Tube abs(const Tube& x);
// sign of a tube, slice- and gate-wise (rigorous).
Tube sign(const Tube& x);
// exp of a tube, slice- and gate-wise (rigorous).
Tube exp(const Tube& x);
// log of a tube, slice- and gate-wise (rigorous).
Tube log(const Tube& x);
// pow of a tube, slice- and gate-wise (rigorous).
Tube pow(const Tube& x, int n);
// pow of a tube, slice- and gate-wise (rigorous).
Tube pow(const Tube& x, double p);
// pow of a tube, slice- and gate-wise (rigorous).
Tube pow(const Tube& x, const Interval& p);
// pow of a tube, slice- and gate-wise (rigorous).
Tube pow(const Tube& x, const Tube& p);
// root of a tube, slice- and gate-wise (rigorous).
Tube root(const Tube& x, int n);
// sin of a tube, slice- and gate-wise (rigorous; by rows: within a few ulps
// of the scalar sin, not its bits).
Tube sin(const Tube& x);
// cos of a tube, slice- and gate-wise (rigorous; by rows, as sin).
Tube cos(const Tube& x);
// tan of a tube, slice- and gate-wise (rigorous).
Tube tan(const Tube& x);
// asin of a tube, slice- and gate-wise (rigorous).
Tube asin(const Tube& x);
// acos of a tube, slice- and gate-wise (rigorous).
Tube acos(const Tube& x);
// atan of a tube, slice- and gate-wise (rigorous).
Tube atan(const Tube& x);
// sinh of a tube, slice- and gate-wise (rigorous).
Tube sinh(const Tube& x);
// cosh of a tube, slice- and gate-wise (rigorous).
Tube cosh(const Tube& x);
// tanh of a tube, slice- and gate-wise (rigorous).
Tube tanh(const Tube& x);
Tube atan2(const Tube& y, const Tube& x);  // y first, like atan2(Interval, Interval)
// atan2 of a tube, slice- and gate-wise (rigorous).
Tube atan2(const Tube& y, const Interval& x);
// atan2 of a tube, slice- and gate-wise (rigorous).
Tube atan2(const Interval& y, const Tube& x);
// min of a tube, slice- and gate-wise (rigorous).
Tube min(const Tube& x, const Tube& y);
// max of a tube, slice- and gate-wise (rigorous).
Tube max(const Tube& x, const Tube& y);

}  // namespace sillage
