#include "sillage/dynamics/heading_common.h"

#include <cmath>

#include "sillage/cn/tube_changes.h"
#include "sillage/error.h"

#include "sillage/interval/elementary.h"

namespace sillage::detail {

Interval box_direction(const Interval& dx, const Interval& dy) {
  const Interval a = atan2(dy, dx), b = atan2(-dy, -dx) + Interval::pi();
  return a.diam() <= b.diam() ? a : b;
}

Interval periodic_meet(const Interval& s, const Interval& r) {
  if (s.is_unbounded() || r.is_unbounded() || s.diam() > 1e6) return s;
  const Interval period = Interval::two_pi();
  const auto shifted = [&](double n) { return (r + period * Interval(n)) & s; };
  // The candidate turns n, one more on each side than the double estimate (rounding).
  double lo = std::floor((s.lb() - r.ub()) / (2 * M_PI)) - 1, hi = std::ceil((s.ub() - r.lb()) / (2 * M_PI)) + 1;
  while (lo <= hi && shifted(lo).is_empty()) ++lo;
  while (hi >= lo && shifted(hi).is_empty()) --hi;
  if (lo > hi) return Interval::empty();
  return shifted(lo) | shifted(hi);
}

bool finish_heading(bool ok, Tube& px, Tube& py, Tube& psi) {
  if (!ok) {
    px.set(Interval::empty()), py.set(Interval::empty()), psi.set(Interval::empty());
    return false;
  }
  return true;
}

HeadingNodeBase::HeadingNodeBase(const std::string& name, const std::vector<BoundDomain>& args, std::size_t count,
                                 const char* what)
    : TubeNode(name, args) {
  if (args.size() != count) {
    throw DimensionError(where() + ": expects " + what + ", got " + std::to_string(args.size()) + " tubes");
  }
  whole_tubes(0, count, what);
}

bool HeadingNodeBase::run_heading(NodeRun& r, const std::function<bool(HeadingEmptyAt&)>& contract) const {
  thread_local TubeSnapshot before[3];  // scratch: per thread, never shared by two runs
  for (std::size_t i = 0; i < 3; ++i) before[i].take(tube_arg(i));
  HeadingEmptyAt at;
  const bool ok = contract(at);
  for (std::size_t i = 0; i < 3; ++i) changes(r, i).diff(before[i], tube_arg(i));
  if (!ok && at.atom != kNoAtom) r.empty_at = offset(at.tube) + at.atom;
  return ok;
}

}  // namespace sillage::detail
