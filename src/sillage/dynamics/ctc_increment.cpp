#include "sillage/dynamics/ctc_increment.h"

#include "sillage/error.h"

namespace sillage {

bool CtcIncrement::contract(Tube& x, const Tube& i) const {
  if (x.tdomain() != i.tdomain()) throw DimensionError("CtcIncrement::contract(x, i): x and i are not on one TDomain");
  Tube::Writer w = x.write();
  const std::span<Interval> g = w.gates();
  const auto& inc = i.data().slices;
  const std::size_t n = x.nb_slices();
  bool changed = false, ok = true;
  const auto narrow = [&](Interval& g, const Interval& h) {
    const Interval r = g & h;
    if (r != g) {
      g = r;
      changed = true;
    }
    ok = ok && !r.is_empty();
  };
  for (std::size_t k = 0; k < n && ok; ++k) narrow(g[k + 1], g[k] + inc[k]);
  for (std::size_t k = n; k-- > 0 && ok;) narrow(g[k], g[k + 1] - inc[k]);
  w.commit(ok && changed);
  if (!ok) x.set(Interval::empty());  // no trajectory
  return ok;
}

bool CtcIncrement::contract(TubeVector& x, const TubeVector& i) const {
  if (x.size() != i.size()) {
    throw DimensionError("CtcIncrement::contract(x, i): x has " + std::to_string(x.size()) + " components, i " +
                         std::to_string(i.size()));
  }
  bool ok = true;
  for (std::size_t c = 0; c < x.size() && ok; ++c) ok = contract(x[c], i[c]);
  if (!ok) x.set(IntervalVector(x.size(), Interval::empty()));  // no trajectory: every component empty
  return ok;
}

}  // namespace sillage
