#pragma once
// The true trajectory of the heading tests: a vehicle at speed s turning at
// rate b from heading a, its direction of travel off its heading by a constant
// e: ψ(t) = a + b t, φ = ψ + e,
// p(t) = p0 + (s / b) (sin(φ(t)) − sin(φ(0)), cos(φ(0)) − cos(φ(t))).
#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"

namespace sillage::test {

struct Turning {
  double a, b, s, e, x0, y0;
  Interval psi(const Interval& t) const { return Interval(a) + Interval(b) * t; }
  Interval phi(const Interval& t) const { return psi(t) + Interval(e); }
  Interval x(const Interval& t) const {
    return Interval(x0) + Interval(s) / Interval(b) * (sin(phi(t)) - sin(phi(Interval(0.0))));
  }
  Interval y(const Interval& t) const {
    return Interval(y0) + Interval(s) / Interval(b) * (cos(phi(Interval(0.0))) - cos(phi(t)));
  }
};

}  // namespace sillage::test
