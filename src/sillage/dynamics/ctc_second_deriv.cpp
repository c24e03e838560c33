#include "sillage/dynamics/ctc_second_deriv.h"

#include <algorithm>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "sillage/dynamics/deriv_sweep.h"
#include "sillage/error.h"

namespace sillage {

namespace {

// The rule on slices first..last of x (contract()'s, slice by slice); false
// when a slice is left empty. `changed`: whether one moved.
bool bow_rule(const TDomain& td, std::span<Interval> s, std::span<const Interval> g, std::span<const Interval> acc,
              std::size_t first, std::size_t last, bool& changed) {
  for (std::size_t k = first; k <= last; ++k) {
    if (acc[k].is_unbounded()) continue;  // no bound: nothing learned
    const Interval bow = Interval(0.0) | sqr(td.slice_width(k)) / Interval(8.0);
    const Interval r = s[k] & ((g[k] | g[k + 1]) - acc[k] * bow);
    if (r != s[k]) s[k] = r, changed = true;
    if (r.is_empty()) return false;
  }
  return true;
}

void check_pair(const Tube& x, const Tube& a, const char* where) {
  if (x.tdomain() != a.tdomain()) throw DimensionError(std::string(where) + ": x and a are not on one TDomain");
}

}  // namespace

bool CtcSecondDeriv::contract(Tube& x, const Tube& a) const {
  check_pair(x, a, "CtcSecondDeriv::contract(x, a)");
  bool changed = false, ok = !x.is_empty() && !a.is_empty();
  {
    Tube::Writer w = x.write();
    ok = ok && bow_rule(*x.tdomain(), w.slices(), w.gates(), a.data().slices, 0, x.nb_slices() - 1, changed);
    w.commit(ok && changed);
  }
  if (!ok) x.set(Interval::empty());  // no trajectory
  return ok;
}

// Slice k of x depends on its gates and on slice k of a only: the slices
// next to what changed are all the rule changes (one more on each side for
// a change of gate first or last + 1).
bool CtcSecondDeriv::contract_local(Tube& x, const Tube& a, std::size_t first, std::size_t last,
                                    const TubeChanges& changes) const {
  const char* where = "CtcSecondDeriv::contract_local(x, a, first, last)";
  check_pair(x, a, where);
  detail::check_deriv_range(x.nb_slices(), first, last, where);
  first = first > 0 ? first - 1 : 0;
  last = std::min(last + 1, x.nb_slices() - 1);
  // contract()'s emptiness test where something may have changed.
  bool ok = true, changed = false;
  for (const Tube* t : std::initializer_list<const Tube*>{&x, &a}) {
    for (std::size_t k = first; k <= last; ++k) ok = ok && !t->slice(k).is_empty() && !t->gate(k).is_empty();
    ok = ok && !t->gate(last + 1).is_empty();
  }
  {
    Tube::Writer w = x.write();
    thread_local std::vector<Interval> was;  // slices first..last before, to report what shrank
    was.assign(w.slices().begin() + static_cast<std::ptrdiff_t>(first),
               w.slices().begin() + static_cast<std::ptrdiff_t>(last + 1));
    ok = ok && bow_rule(*x.tdomain(), w.slices(), w.gates(), a.data().slices, first, last, changed);
    if (ok) {
      for (std::size_t k = first; k <= last; ++k) changes.slice(k, was[k - first], w.slices()[k]);
    }
    w.commit(ok && changed);
  }
  if (!ok) x.set(Interval::empty());  // no trajectory
  return ok;
}

}  // namespace sillage
