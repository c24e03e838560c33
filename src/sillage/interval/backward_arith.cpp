// Backward projections of the arithmetic operators and of the piecewise
// functions (abs, min, max, sign). Each is the exact projection of the
// relation, enclosed with outward rounding; a relation that splits a domain in
// two pieces (x1 * x2 = y with 0 in x2) intersects each piece with the
// argument before taking the hull.
#include <utility>

#include "sillage/interval/backward.h"
#include "sillage/interval/backward_detail.h"

namespace sillage {

using namespace detail;
using rounding::kInf;

bool bwd_add(const Interval& y_in, Interval& x1, Interval& x2) {
  const Interval y = y_in;  // y may alias an argument
  x1 &= y - x2;
  x2 &= y - x1;
  return settle(x1, x2);
}

bool bwd_sub(const Interval& y_in, Interval& x1, Interval& x2) {
  const Interval y = y_in;
  x1 &= y + x2;
  x2 &= x1 - y;
  return settle(x1, x2);
}

bool bwd_mul(const Interval& y_in, Interval& x1, Interval& x2) {
  const Interval y = y_in;
  if (y.is_empty()) x1.set_empty();
  x1 = meet_pieces(x1, div2(y, x2));
  x2 = meet_pieces(x2, div2(y, x1));
  return settle(x1, x2);
}

bool bwd_div(const Interval& y_in, Interval& x1, Interval& x2) {
  // y = x1 / x2 with x2 != 0, i.e. x1 = y * x2.
  const Interval y = y_in;
  if (y.is_empty() || (x2.lb() == 0 && x2.ub() == 0)) x1.set_empty();
  x1 &= y * x2;
  x2 = meet_pieces(x2, div2(x1, y));
  if (x2.lb() == 0 && x2.ub() == 0) x2.set_empty();  // only x2 = 0 was left
  x1 &= y * x2;
  return settle(x1, x2);
}

bool bwd_neg(const Interval& y, Interval& x) {
  x &= -y;
  return settle(x);
}

bool bwd_sqr(const Interval& y, Interval& x) {
  // Both branches +-sqrt(y), each intersected with x; sqrt is set-based (y < 0 ignored).
  x = meet_symmetric(x, sqrt(y));
  return settle(x);
}

bool bwd_sqrt(const Interval& y, Interval& x) {
  const Interval r = y & Interval::pos_reals();
  x &= sqr(r) & Interval::pos_reals();
  if (r.is_empty()) x.set_empty();
  return settle(x);
}

bool bwd_abs(const Interval& y, Interval& x) {
  x = meet_symmetric(x, y & Interval::pos_reals());
  return settle(x);
}

bool bwd_min(const Interval& y_in, Interval& x1, Interval& x2) {
  // x1 is either the minimum (x1 in y, x1 <= x2) or above a minimum x2 in y.
  const Interval y = y_in;
  auto project = [&y](const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    const Interval as_min = a & y & Interval(-kInf, b.ub());
    const Interval b_in_y = b & y;
    const Interval above = b_in_y.is_empty() ? Interval::empty() : a & Interval(b_in_y.lb(), kInf);
    return as_min | above;
  };
  x1 = project(x1, x2);
  x2 = project(x2, x1);
  return settle(x1, x2);
}

bool bwd_max(const Interval& y, Interval& x1, Interval& x2) {
  // max(a, b) = -min(-a, -b)
  Interval n1 = -x1, n2 = -x2;
  const bool ok = bwd_min(-y, n1, n2);
  x1 = -n1;
  x2 = -n2;
  return ok;
}

bool bwd_sign(const Interval& y, Interval& x) {
  // Open half-lines are enclosed by closed ones: the reals in (0, 1e-324) are solutions too.
  Interval r = Interval::empty();
  if (y.contains(1)) r |= x & Interval::pos_reals();
  if (y.contains(0)) r |= x & Interval(0.0);
  if (y.contains(-1)) r |= x & Interval::neg_reals();
  x = r;
  return settle(x);
}

}  // namespace sillage
