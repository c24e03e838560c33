// Backward projections of sin, cos, tan (periodic preimages) and atan2.
//
// The preimage of [y] by a periodic function is a union of branches repeated
// with the period. Intersected with [x], its hull runs from the first branch
// that meets [x] to the last one: only the two end branches are computed,
// tightly, and everything between them is kept (hull over the branches).
#include <algorithm>
#include <cmath>

#include "sillage/interval/backward.h"
#include "sillage/interval/backward_detail.h"
#include "sillage/interval/elementary.h"

namespace sillage {

namespace {

using namespace detail;
using rounding::kInf;

// The union over integers k of branch[j] + k * period. The branches are outer
// enclosures of the true ones, given in increasing order within a period that
// starts near `start`; true branches, listed period after period, have
// nondecreasing lower and upper bounds (this is what makes the scans exact).
struct PeriodicSet {
  Interval branch[2];
  int count;
  Interval period;
  double start;

  Interval shifted(int j, double k) const { return branch[j] + Interval(k) * period; }
};

// Beyond this the enclosure of k * period is too wide to help: keep the bound.
constexpr double kMaxReducible = 0x1p40;

enum class Scan { kFound, kEmpty, kUnknown };

// The first branch (in increasing order) that reaches xl gives the lower bound.
Scan lowest_from(const PeriodicSet& s, double xl, double xu, double& lo) {
  double k = std::floor((xl - s.start) / s.period.mid()) - 1;
  for (int guard = 0; s.shifted(s.count - 1, k).ub() >= xl; ++guard) {  // all of period k below xl
    if (guard > 4) return Scan::kUnknown;
    k -= 1;
  }
  for (int p = 1; p <= 6; ++p) {
    for (int j = 0; j < s.count; ++j) {
      const Interval b = s.shifted(j, k + p);
      if (b.ub() >= xl) {
        if (b.lb() > xu) return Scan::kEmpty;  // it and every later branch lie above x
        lo = std::max(xl, b.lb());
        return Scan::kFound;
      }
    }
  }
  return Scan::kUnknown;
}

// Mirror image: the last branch that reaches down to xu gives the upper bound.
Scan highest_from(const PeriodicSet& s, double xl, double xu, double& hi) {
  double k = std::floor((xu - s.start) / s.period.mid()) + 1;
  for (int guard = 0; s.shifted(0, k).lb() <= xu; ++guard) {  // all of period k above xu
    if (guard > 4) return Scan::kUnknown;
    k += 1;
  }
  for (int p = 1; p <= 6; ++p) {
    for (int j = s.count - 1; j >= 0; --j) {
      const Interval b = s.shifted(j, k - p);
      if (b.lb() <= xu) {
        if (b.ub() < xl) return Scan::kEmpty;
        hi = std::min(xu, b.ub());
        return Scan::kFound;
      }
    }
  }
  return Scan::kUnknown;
}

bool contract_periodic(const PeriodicSet& s, Interval& x) {
  if (x.is_empty()) return false;
  double lo = x.lb(), hi = x.ub();
  if (std::isfinite(lo) && std::fabs(lo) <= kMaxReducible) {
    if (lowest_from(s, x.lb(), x.ub(), lo) == Scan::kEmpty) lo = kInf;
  }
  if (std::isfinite(hi) && std::fabs(hi) <= kMaxReducible) {
    if (highest_from(s, x.lb(), x.ub(), hi) == Scan::kEmpty) hi = -kInf;
  }
  if (!(lo <= hi)) {
    x.set_empty();
    return false;
  }
  x = Interval(lo, hi);
  return true;
}

}  // namespace

bool bwd_sin(const Interval& y, Interval& x) {
  const Interval v = y & Interval(-1.0, 1.0);
  if (v.is_empty()) x.set_empty();
  if (x.is_empty()) return false;
  if (v.lb() == -1 && v.ub() == 1) return true;
  // Branches asin(v) and pi - asin(v), period 2 pi.
  const Interval a1 = asin(Interval(v.lb())), a2 = asin(Interval(v.ub())), pi = Interval::pi();
  const PeriodicSet s{{Interval(a1.lb(), a2.ub()), Interval((pi - a2).lb(), (pi - a1).ub())},
                      2,
                      Interval::two_pi(),
                      -Interval::half_pi().mid()};
  return contract_periodic(s, x);
}

bool bwd_cos(const Interval& y, Interval& x) {
  const Interval v = y & Interval(-1.0, 1.0);
  if (v.is_empty()) x.set_empty();
  if (x.is_empty()) return false;
  if (v.lb() == -1 && v.ub() == 1) return true;
  // Branches acos(v) and 2 pi - acos(v), period 2 pi.
  const Interval c1 = acos(Interval(v.ub())), c2 = acos(Interval(v.lb())), tau = Interval::two_pi();
  const PeriodicSet s{
      {Interval(c1.lb(), c2.ub()), Interval((tau - c2).lb(), (tau - c1).ub())}, 2, tau, 0.0};
  return contract_periodic(s, x);
}

bool bwd_tan(const Interval& y, Interval& x) {
  if (y.is_empty()) x.set_empty();
  if (x.is_empty()) return false;
  if (y.is_all_reals()) return true;
  // One branch atan(y), period pi (its closure reaches the poles when y is unbounded).
  const double h = Interval::half_pi().ub();
  const double lo = y.lb() == -kInf ? -h : atan(Interval(y.lb())).lb();
  const double hi = y.ub() == kInf ? h : atan(Interval(y.ub())).ub();
  const PeriodicSet s{{Interval(lo, hi), Interval::empty()}, 1, Interval::pi(), -Interval::half_pi().mid()};
  return contract_periodic(s, x);
}

bool bwd_atan2(const Interval& theta, Interval& y, Interval& x) {
  // (x, y) = r (cos t, sin t) with r > 0 and t in theta. Octant by octant:
  // near the x axis y = tan(t) x, near the y axis x = cot(t) y (both bounded
  // there), with the signs of the quadrant; the results are hulled.
  const Interval pi = Interval::pi();
  const Interval th = theta & Interval(-pi.ub(), pi.ub());
  if (th.is_empty()) x.set_empty();
  if (!settle(x, y)) return false;
  const Interval quarter = pi / Interval(4.0);  // exact: a power-of-two scaling
  Interval hx = Interval::empty(), hy = Interval::empty();
  for (int k = -4; k < 4; ++k) {  // octant [k pi/4, (k+1) pi/4]
    const Interval t = th & Interval((Interval(k) * quarter).lb(), (Interval(k + 1) * quarter).ub());
    if (t.is_empty()) continue;
    Interval xk = x & (k >= -2 && k <= 1 ? Interval::pos_reals() : Interval::neg_reals());
    Interval yk = y & (k >= 0 ? Interval::pos_reals() : Interval::neg_reals());
    if (xk.is_empty() || yk.is_empty()) continue;
    if (k == -4 || k == -1 || k == 0 || k == 3) {
      // tan is increasing on each of these octants.
      Interval tn(tan(Interval(t.lb())).lb(), tan(Interval(t.ub())).ub());
      yk &= tn * xk;
      bwd_mul(yk, xk, tn);
      yk &= tn * xk;
    } else {
      // cot = cos / sin is decreasing on (-pi, 0) and on (0, pi).
      auto cot = [](double a) { return cos(Interval(a)) / sin(Interval(a)); };
      Interval ct(cot(t.ub()).lb(), cot(t.lb()).ub());
      xk &= ct * yk;
      bwd_mul(xk, yk, ct);
      xk &= ct * yk;
    }
    if (xk.is_empty() || yk.is_empty()) continue;
    if (xk == Interval(0.0) && yk == Interval(0.0)) continue;  // atan2(0, 0) is undefined
    hx |= xk;
    hy |= yk;
  }
  x = hx;
  y = hy;
  return settle(x, y);
}

}  // namespace sillage
