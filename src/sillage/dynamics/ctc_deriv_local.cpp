// CtcDeriv::contract_local: the fixed point of x' = v after a change in
// slices first..last of a tube that was a fixed point before (a network
// node's run after what woke it). The sweeps of contract() start at the
// change and go on, by blocks that double, while they still move a gate: a
// sweep beyond changes nothing there (the tube was a fixed point), so the
// result is contract()'s at the cost of the reach of the change.
#include <algorithm>
#include <vector>

#include "sillage/cn/tube_originals.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/deriv_sweep.h"

namespace sillage {

namespace {

using detail::DerivSweep;

constexpr std::size_t kFirstStep = 16;  // slices of the first block beyond the change

}  // namespace

bool CtcDeriv::contract_local(Tube& x, const Tube& v, std::size_t first, std::size_t last,
                              const TubeChanges& changes) const {
  const char* where = "CtcDeriv::contract_local(x, v, first, last)";
  detail::check_deriv_pair(x, v, where);
  detail::check_real(x, where);
  const std::size_t n = x.nb_slices();
  detail::check_deriv_range(n, first, last, where);
  if (propag_ != TimePropag::FWD_BWD) {  // one pass is no fixed point: the whole pass, as contract()
    TubeSnapshot snapshot;
    snapshot.take(x);
    const bool ok = contract(x, v);
    if (ok) changes.diff(snapshot, x);
    return ok;
  }
  const auto vg = v.gates();
  bool ok = true, changed = false;
  {
    Tube::Writer w = x.write();
    const auto s = w.slices(), g = w.gates();
    thread_local detail::TubeOriginals before;  // reused: a network runs this at every update
    before.start(s, g);
    const double* t = x.tdomain()->times().data();
    const Interval* vs = v.data().slices.data();
    // One block: false on emptiness (an empty gate of v leaves no derivative, as contract()).
    const auto sweep = [&](DerivSweep kind, std::size_t a, std::size_t b) {
      for (std::size_t k = a; k <= b + 1; ++k) {
        if (vg[k].is_empty()) return false;
      }
      before.cover(a, b);
      return detail::deriv_sweep(kind, t, s.data(), g.data(), vs, a, b, changed);
    };
    // Forward from the change, while the gate after the block moves.
    std::size_t hi = last;
    {
      std::size_t a = first, b = last, step = kFirstStep;
      for (;;) {
        const Interval after = g[b + 1];
        if (!(ok = sweep(DerivSweep::FwdBwdForward, a, b))) break;
        if (b + 1 >= n || g[b + 1] == after) break;
        a = b + 1;
        b = std::min(n - 1, a + step - 1);
        step *= 2;
      }
      hi = b;
    }
    // Backward from there, while the gate before the block moves (the first
    // block against the gate's value before any sweep: the forward rule may
    // have moved it).
    if (ok) {
      std::size_t a = first, b = hi, step = kFirstStep;
      for (;;) {
        before.cover(a, b);
        const Interval start = a == first ? before.gate(first) : g[a];
        if (!(ok = sweep(DerivSweep::FwdBwdBackward, a, b))) break;
        if (a == 0 || g[a] == start) break;
        b = a - 1;
        a = b + 1 > step ? b + 1 - step : 0;
        step *= 2;
      }
    }
    if (ok) before.report(changes);
    w.commit(ok && changed);
  }
  if (!ok) x.set(Interval::empty());
  return ok;
}

}  // namespace sillage
