// Interval + - * / sqr sqrt, out of line: the kernels (arith_kernels.h) and
// the inline assembly behind them stay internal. Each operator holds both
// rounding paths inlined and picks one by a flag set once per process; the
// flag never changes between calls, so its branch is always predicted (a
// function pointer would cost a second, indirect call on top of this one).
#include "sillage/interval/arith_kernels.h"
#include "sillage/interval/interval.h"

namespace sillage {

namespace {

// The kernel k over the rounding path of this process, as an Interval.
template <class Kernel>
[[gnu::always_inline]] inline Interval on_path(Kernel k) {
  const detail::BoundPair r = detail::with_rounding(k);
  return Interval::from_bounds_unchecked(r.lo, r.hi);
}

}  // namespace

Interval operator+(const Interval& x, const Interval& y) {
  return on_path([&]<class R>(R) { return detail::add_bounds<R>(x.lb(), x.ub(), y.lb(), y.ub()); });
}

Interval operator-(const Interval& x, const Interval& y) {
  return on_path([&]<class R>(R) { return detail::sub_bounds<R>(x.lb(), x.ub(), y.lb(), y.ub()); });
}

Interval operator*(const Interval& x, const Interval& y) {
  return on_path([&]<class R>(R) { return detail::mul_bounds<R>(x.lb(), x.ub(), y.lb(), y.ub()); });
}

Interval operator/(const Interval& x, const Interval& y) {
  return on_path([&]<class R>(R) { return detail::div_bounds<R>(x.lb(), x.ub(), y.lb(), y.ub()); });
}

Interval sqr(const Interval& x) {
  return on_path([&]<class R>(R) { return detail::sqr_bounds<R>(x.lb(), x.ub()); });
}

Interval sqrt(const Interval& x) {
  return on_path([&]<class R>(R) { return detail::sqrt_bounds<R>(x.lb(), x.ub()); });
}

}  // namespace sillage
