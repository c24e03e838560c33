#include "sillage/dynamics/ctc_second_deriv.h"

#include "sillage/error.h"

namespace sillage {

bool CtcSecondDeriv::contract(Tube& x, const Tube& a) const {
  if (x.tdomain() != a.tdomain()) {
    throw DimensionError("CtcSecondDeriv::contract(x, a): x and a are not on one TDomain");
  }
  TubeData& d = x.data();
  const auto& acc = a.data().slices;
  const auto& td = *x.tdomain();
  bool changed = false, ok = !x.is_empty() && !a.is_empty();
  for (std::size_t k = 0; k < x.nb_slices() && ok; ++k) {
    if (acc[k].is_unbounded()) continue;  // no bound: nothing learned
    const Interval bow = Interval(0.0) | sqr(td.slice_width(k)) / Interval(8.0);
    const Interval r = d.slices[k] & ((d.gates[k] | d.gates[k + 1]) - acc[k] * bow);
    if (r != d.slices[k]) d.slices[k] = r, changed = true;
    ok = !r.is_empty();
  }
  if (!ok) x.set(Interval::empty());  // no trajectory
  else if (changed) x.touch();
  return ok;
}

}  // namespace sillage
