#include "sillage/dynamics/ctc_deriv_angle.h"

#include <algorithm>
#include <span>
#include <utility>

#include "sillage/dynamics/deriv_sweep.h"
#include "sillage/interval/angle.h"

namespace sillage {

namespace {

// The slice rule anchored at gate a (not the whole circle); v is the rate
// from a towards b (negated for the backward anchor). False if empty.
bool anchored_rule(Interval& a, Interval& s, Interval& b, const Interval& v, const Interval& dt) {
  const Interval span = Interval(0.0) | dt;
  // The lift through a is a real number: every copy of b (and s) it may reach is kept.
  const Interval b_lift = angle_lift(b, a + dt * v);
  Interval s_lift = angle_lift(s, a + span * v);
  const Interval a_new = a & (b_lift - dt * v);
  s_lift &= (a_new + span * v) & (b_lift - (dt - span) * v);
  a = a_new;
  b = angle_meet(b, b_lift);
  s = angle_meet(s, s_lift);
  return !a.is_empty() && !b.is_empty() && !s.is_empty();
}

// The rule on slice k: gates into the slice, then anchored at the narrower
// usable gate. `changed` is set when a bound moved.
bool slice_rule(Interval& a, Interval& s, Interval& b, const Interval& v, const Interval& dt, bool& changed) {
  const Interval a0 = a, s0 = s, b0 = b;
  a = angle_meet(a, s);
  b = angle_meet(b, s);
  bool ok = !a.is_empty() && !b.is_empty();
  if (ok && !v.is_unbounded()) {
    if (!angle_is_circle(a)) ok = anchored_rule(a, s, b, v, dt);
    else if (!angle_is_circle(b)) ok = anchored_rule(b, s, a, -v, dt);
  }
  changed = changed || a != a0 || s != s0 || b != b0;
  return ok;
}

}  // namespace

bool CtcDerivAngle::contract(Tube& x, const Tube& v) const {
  detail::check_deriv_pair(x, v, "CtcDerivAngle::contract(x, v)");
  return contract_local(x, v, 0, x.nb_slices() - 1, TubeChanges());
}

bool CtcDerivAngle::contract_local(Tube& x, const Tube& v, std::size_t first, std::size_t last,
                                   const TubeChanges& changes) const {
  const char* where = "CtcDerivAngle::contract_local(x, v, first, last)";
  detail::check_deriv_pair(x, v, where);
  const std::size_t n = x.nb_slices();
  detail::check_deriv_range(n, first, last, where);
  const TDomain& td = *x.tdomain();
  const std::span<const Interval> rate = v.data().slices;
  bool ok = !x.is_empty(), changed = false;
  {
    Tube::Writer w = x.write();
    const std::span<Interval> s = w.slices(), g = w.gates();
    // Applies the rule on slice k, reporting what shrank; whether gate `watched` moved.
    const auto apply = [&](std::size_t k, std::size_t watched) {
      const Interval a0 = g[k], s0 = s[k], b0 = g[k + 1], gw = g[watched];
      bool moved = false;
      ok = ok && !rate[k].is_empty() && slice_rule(g[k], s[k], g[k + 1], rate[k], td.slice_width(k), moved);
      if (moved) {
        changed = true;
        changes.gate(k, a0, g[k]);
        changes.slice(k, s0, s[k]);
        changes.gate(k + 1, b0, g[k + 1]);
      }
      return g[watched] != gw;
    };
    // Forward from first, on while gates move past last; then backward likewise.
    for (std::size_t k = first; ok && k < n; ++k)
      if (!apply(k, k + 1) && k > last) break;
    for (std::size_t k = last + 1; ok && k-- > 0;)
      if (!apply(k, k) && k < first) break;
    w.commit(ok && changed);
  }
  if (!ok) x.set(Interval::empty());  // no trajectory
  return ok;
}

}  // namespace sillage
