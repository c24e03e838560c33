#include "sillage/dynamics/ctc_second_deriv.h"

#include "sillage/error.h"

namespace sillage {

bool CtcSecondDeriv::contract(Tube& x, const Tube& a) const {
  if (x.tdomain() != a.tdomain()) {
    throw DimensionError("CtcSecondDeriv::contract(x, a): x and a are not on one TDomain");
  }
  Tube::Writer w = x.write();
  const std::span<Interval> s = w.slices(), g = w.gates();
  const auto& acc = a.data().slices;
  const auto& td = *x.tdomain();
  bool changed = false, ok = !x.is_empty() && !a.is_empty();
  for (std::size_t k = 0; k < x.nb_slices() && ok; ++k) {
    if (acc[k].is_unbounded()) continue;  // no bound: nothing learned
    const Interval bow = Interval(0.0) | sqr(td.slice_width(k)) / Interval(8.0);
    const Interval r = s[k] & ((g[k] | g[k + 1]) - acc[k] * bow);
    if (r != s[k]) s[k] = r, changed = true;
    ok = !r.is_empty();
  }
  w.commit(ok && changed);
  if (!ok) x.set(Interval::empty());  // no trajectory
  return ok;
}

}  // namespace sillage
