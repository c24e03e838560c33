#include "sillage/dynamics/ctc_increment.h"

#include <algorithm>

#include "sillage/cn/tube_originals.h"
#include "sillage/dynamics/deriv_sweep.h"
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

// The rules of contract() in its order, from slice first: forward while a
// gate after last moves, backward from there while a gate before first
// moves. Beyond, the rules would change nothing (x was their fixed point).
bool CtcIncrement::contract_local(Tube& x, const Tube& i, std::size_t first, std::size_t last,
                                  const TubeChanges& changes) const {
  const char* where = "CtcIncrement::contract_local(x, i, first, last)";
  if (x.tdomain() != i.tdomain()) throw DimensionError(std::string(where) + ": x and i are not on one TDomain");
  const std::size_t n = x.nb_slices();
  detail::check_deriv_range(n, first, last, where);
  bool changed = false, ok = true;
  {
    Tube::Writer w = x.write();
    const std::span<Interval> g = w.gates();
    const auto& inc = i.data().slices;
    thread_local detail::TubeOriginals before;  // reused: a network runs this at every update
    before.start(w.slices(), g);
    before.cover(first, last);  // the gates the rules narrow: k + 1 forward, k backward (slice k's)
    // Gate j ∩= h as contract() does; true if it moved.
    const auto narrow = [&](std::size_t j, const Interval& h) {
      const Interval r = g[j] & h;
      const bool moved = r != g[j];
      if (moved) g[j] = r, changed = true;
      ok = !r.is_empty();
      return moved;
    };
    std::size_t top = n - 1;
    for (std::size_t k = first; k < n; ++k) {
      before.reach(k, n);
      const bool moved = narrow(k + 1, g[k] + inc[k]);
      if (!ok) break;
      if (k > last && !moved) {
        top = k;
        break;
      }
    }
    for (std::size_t k = top + 1; ok && k-- > 0;) {
      before.reach(k, n);
      if (!narrow(k, g[k + 1] - inc[k]) && k < first) break;
    }
    if (ok) before.report(changes);
    w.commit(ok && changed);
  }
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
