#include "sillage/tube/time_box_ctc.h"

#include "sillage/ctc/ctc_function.h"
#include "sillage/tube/tube_atoms.h"

namespace sillage::detail {

namespace {

// Boxes contracted together (one HC4 batch); their rows stay in cache.
constexpr std::size_t kChunk = 256;

// Contracts the boxes j < count stored by columns: variable v of box j at
// box[v * count + j] (empty in a variable if proven inconsistent).
void contract_boxes(const Ctc& ctc, const CtcFunction* f, std::vector<Interval>& box, std::size_t count) {
  const std::size_t n = ctc.nb_vars();
  if (f) {
    std::vector<Interval*> cols(n);
    for (std::size_t v = 0; v < n; ++v) cols[v] = box.data() + v * count;
    f->function().hc4_revise_batch(cols, count, f->image());
    return;
  }
  IntervalVector b(n);
  for (std::size_t j = 0; j < count; ++j) {
    for (std::size_t v = 0; v < n; ++v) b[v] = box[v * count + j];
    ctc.contract(b);
    for (std::size_t v = 0; v < n; ++v) box[v * count + j] = b[v];
  }
}

}  // namespace

std::size_t contract_time_elements(const Ctc& ctc, const std::vector<TimeVar>& vars,
                                   std::span<const std::size_t> atoms, IntervalVector& params,
                                   const TimeChange& changed) {
  const std::size_t n = vars.size();
  const auto* f = dynamic_cast<const CtcFunction*>(&ctc);
  bool constants = false;
  std::size_t last = 0;  // the last atom (gate N)
  for (const TimeVar& x : vars) {
    constants = constants || !x.tube;
    if (x.tube) last = 2 * x.tube->nb_slices();
  }
  const std::size_t chunk = constants ? 1 : kChunk;
  std::vector<Interval> box(n * chunk);  // the tubes keep the values before contraction
  std::vector<std::size_t> ids;  // the time atoms of the chunk
  std::vector<char> touched(n, 0);
  const auto touch = [&] {
    for (std::size_t v = 0; v < n; ++v)
      if (touched[v]) vars[v].tube->touch();
  };
  const auto narrow = [&](std::size_t v, std::size_t i, Interval& x, const Interval& was, const Interval& now) {
    if (changed) changed(v, i, was, now);
    x = now;
    touched[v] = 1;
  };
  // Slices first, then gates (which are intersected with their slices).
  for (const int parity : {1, 0}) {
    for (auto next = atoms.begin(); next != atoms.end();) {
      ids.clear();
      for (; next != atoms.end() && ids.size() < chunk; ++next)
        if (static_cast<int>(*next & 1) == parity) ids.push_back(*next);
      if (ids.empty()) break;
      const std::size_t c = ids.size();
      // Gather: box j in column layout, variable v at v * c + j.
      for (std::size_t j = 0; j < c; ++j) {
        const std::size_t i = ids[j];
        for (std::size_t v = 0; v < n; ++v) {
          if (!vars[v].tube) {
            box[v * c + j] = params[vars[v].param];
            continue;
          }
          TubeData& d = vars[v].tube->data();
          Interval& x = TubeAtoms::time_atom(d, i);
          if (parity == 0) {  // x(t_k) lies in both neighbouring slices
            Interval h = x;
            if (i > 0) h &= d.slices[i / 2 - 1];
            if (i < last) h &= d.slices[i / 2];
            if (h != x) narrow(v, i, x, x, h);
          }
          box[v * c + j] = x;
        }
      }
      contract_boxes(ctc, f, box, c);
      // Scatter, in order: a box proven empty stops there.
      for (std::size_t j = 0; j < c; ++j) {
        const std::size_t i = ids[j];
        bool ok = true;
        for (std::size_t v = 0; v < n; ++v) ok = ok && !box[v * c + j].is_empty();
        for (std::size_t v = 0; v < n; ++v) {
          const Interval got = ok ? box[v * c + j] : Interval::empty();
          if (!vars[v].tube) {
            params[vars[v].param] &= got;
            continue;
          }
          Interval& x = TubeAtoms::time_atom(vars[v].tube->data(), i);
          const Interval now = x & got;
          if (now != x) narrow(v, i, x, x, now);
        }
        if (!ok) {
          params.set_empty();
          touch();
          return i;
        }
      }
    }
  }
  touch();
  return kNoTimeAtom;
}

}  // namespace sillage::detail
