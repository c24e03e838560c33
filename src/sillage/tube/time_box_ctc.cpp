#include "sillage/tube/time_box_ctc.h"

#include <algorithm>
#include <cstring>
#include <optional>

#include "sillage/ctc/ctc_function.h"
#include "sillage/expr/hc4_rows.h"

namespace sillage::detail {

namespace {

// The boxes of a chunk, variable by variable: the rows of the HC4 where the
// contractor is a CtcFunction (filled in place, no copy), else a buffer
// contracted box by box. ok[j] = 0 where box j is proven empty.
class ChunkBoxes {
 public:
  // Boxes per chunk: one HC4 batch (its rows stay in cache); one at a time
  // when some variable is a constant (a parameter narrowed box after box).
  static std::size_t chunk(bool constants) { return constants ? 1 : Hc4Rows::kMaxBoxes; }

  ChunkBoxes(const Ctc& ctc, std::size_t chunk) : ctc_(ctc), f_(dynamic_cast<const CtcFunction*>(&ctc)) {
    if (f_) hc_.emplace(f_->function());
    else box_.resize(ctc.nb_vars() * chunk);
  }
  // Variable v of boxes 0 .. count-1 (the same count until contract).
  Interval* column(std::size_t v, std::size_t count) {
    return hc_ ? hc_->var_row(v, count) : box_.data() + v * count;
  }
  // The contracted boxes are subsets of the boxes written (Hc4Rows says so):
  // no intersection with the tubes' values is needed on the way back.
  bool subsets() const { return hc_.has_value(); }
  const std::uint8_t* contract(std::size_t count) {
    if (hc_) {
      hc_->contract(count, f_->image(), ok_);
      return ok_;
    }
    const std::size_t n = ctc_.nb_vars();
    IntervalVector b(n);
    for (std::size_t j = 0; j < count; ++j) {
      for (std::size_t v = 0; v < n; ++v) b[v] = box_[v * count + j];
      if (!b.is_empty()) ctc_.contract(b);  // an empty element on input is an answer already
      for (std::size_t v = 0; v < n; ++v) box_[v * count + j] = b[v];
      ok_[j] = b.is_empty() ? 0 : 1;
    }
    return ok_;
  }

 private:
  const Ctc& ctc_;
  const CtcFunction* f_;
  std::optional<Hc4Rows> hc_;
  std::vector<Interval> box_;
  std::uint8_t ok_[Hc4Rows::kMaxBoxes];
};

// Gate k of a tube ∩ its neighbouring slices (x(t_k) lies in both; x itself
// stands for a missing one: x & x is x); one expression keeps it in registers.
inline Interval gate_in_slices(const Interval& x, const Interval* slices, std::size_t k, std::size_t nb_slices) {
  return (x & slices[k > 0 ? k - 1 : k]) & (k < nb_slices ? slices[k] : x);
}

// A bound moved from x to y (y ⊆ x, so that this is a change of value).
inline bool moved(const Interval& x, const Interval& y) { return (x.lb() != y.lb()) | (x.ub() != y.ub()); }

[[gnu::noinline]] void tell(const TimeChange& changed, std::size_t v, std::size_t i, Interval was, Interval now) {
  changed(v, i, was, now);
}

}  // namespace

std::size_t contract_time_elements(const Ctc& ctc, const std::vector<TimeVar>& vars,
                                   std::span<const std::size_t> atoms, IntervalVector& params,
                                   const TimeChange& changed) {
  const std::size_t n = vars.size();
  // Each tube's slices and gates (null for a constant), written in place: the
  // storage does not move during the contraction.
  std::vector<Interval*> slices(n, nullptr), gates(n, nullptr);
  std::vector<char> angle(n, 0);  // an angle tube: its gates are not cut by its slices (modulo 2π)
  std::vector<std::optional<Tube::Writer>> writers(n);
  bool constants = false;
  std::size_t nb_slices = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!vars[v].tube) {
      constants = true;
      continue;
    }
    const Tube::Writer& w = writers[v].emplace(vars[v].tube->write());
    slices[v] = w.slices().data();
    gates[v] = w.gates().data();
    nb_slices = w.slices().size();
    angle[v] = vars[v].tube->is_angle();
  }
  const std::size_t chunk = ChunkBoxes::chunk(constants);
  ChunkBoxes boxes(ctc, chunk);  // the tubes keep the values before contraction
  std::vector<std::size_t> ids;  // the time atoms of the chunk
  std::vector<char> touched(n, 0);
  const auto touch = [&] {
    for (std::size_t v = 0; v < n; ++v)
      if (writers[v]) writers[v]->commit(touched[v] != 0);
  };
  // now by value and the callback out of line: an interval whose address is
  // taken goes through memory, two 8-byte stores read back as one 16-byte
  // load, a store-forwarding stall per time element.
  const auto narrow = [&](std::size_t v, std::size_t i, Interval& x, Interval now) {
    if (changed) [[unlikely]] tell(changed, v, i, x, now);
    x = now;
    touched[v] = 1;
  };
  // Slices first, then gates (which are intersected with their slices).
  // Within a chunk the boxes are read and written variable by variable (one
  // column at a time); each variable still sees its atoms in order.
  // Every atom (the usual case): the chunks' ids follow without a scan.
  const bool every_atom = atoms.size() == 2 * nb_slices + 1 && atoms.back() == 2 * nb_slices;  // sorted, distinct
  for (const int parity : {1, 0}) {
    std::size_t next_k = 0;  // every_atom: the first time element of the next chunk
    for (auto next = atoms.begin();;) {
      ids.clear();
      if (every_atom) {
        ids.resize(std::min(chunk, nb_slices + 1 - parity - next_k));
        for (std::size_t j = 0; j < ids.size(); ++j) ids[j] = 2 * (next_k + j) + parity;
        next_k += ids.size();
      } else {
        for (; next != atoms.end() && ids.size() < chunk; ++next)
          if (static_cast<int>(*next & 1) == parity) ids.push_back(*next);
      }
      if (ids.empty()) break;
      const std::size_t c = ids.size();
      // Consecutive time elements k0, k0 + 1, ... (the usual case: every
      // atom) are read and written as blocks.
      const std::size_t k0 = ids[0] / 2;
      const bool run = ids[c - 1] / 2 - k0 == c - 1;
      for (std::size_t v = 0; v < n; ++v) {
        Interval* const col = boxes.column(v, c);
        if (!slices[v]) {
          std::fill(col, col + c, params[vars[v].param]);
          continue;
        }
        Interval* const elems = parity == 1 ? slices[v] : gates[v];
        if (parity == 1 && run) {
          std::copy_n(elems + k0, c, col);
          continue;
        }
        if (angle[v]) {
          for (std::size_t j = 0; j < c; ++j) col[j] = elems[ids[j] / 2];
          continue;
        }
        if (run && !changed) {  // gates k0 .. k0 + c - 1, nobody to tell: no branch per gate
          bool any = false;
          for (std::size_t j = 0; j < c; ++j) {
            Interval& x = elems[k0 + j];
            const Interval h = gate_in_slices(x, slices[v], k0 + j, nb_slices);
            any |= moved(x, h);
            x = h;
            col[j] = h;
          }
          touched[v] |= any;
          continue;
        }
        for (std::size_t j = 0; j < c; ++j) {
          const std::size_t k = ids[j] / 2;
          Interval& x = elems[k];
          if (parity == 1) {
            col[j] = x;
            continue;
          }
          const Interval h = gate_in_slices(x, slices[v], k, nb_slices);
          if (h != x) narrow(v, ids[j], x, h);
          col[j] = h;
        }
      }
      const std::uint8_t* const ok = boxes.contract(c);
      // The boxes before the first one proven empty are written back; that one stops there.
      const auto* const first_empty = static_cast<const std::uint8_t*>(std::memchr(ok, 0, c));
      const std::size_t stop = first_empty ? static_cast<std::size_t>(first_empty - ok) : c;
      for (std::size_t v = 0; v < n; ++v) {
        const Interval* const col = boxes.column(v, c);
        if (!slices[v]) {
          for (std::size_t j = 0; j < stop; ++j) params[vars[v].param] &= col[j];
          continue;
        }
        Interval* const elems = parity == 1 ? slices[v] : gates[v];
        if (boxes.subsets() && run) {  // col[j] ⊆ x: a change is a moved bound
          Interval* const x = elems + k0;
          if (!changed) {  // nobody to tell: one pass without a branch, one copy
            bool any = false;
            for (std::size_t j = 0; j < stop; ++j) any |= moved(x[j], col[j]);
            std::copy_n(col, stop, x);
            touched[v] |= any;
          } else {
            for (std::size_t j = 0; j < stop; ++j)
              if (moved(x[j], col[j])) narrow(v, ids[j], x[j], col[j]);
          }
        } else {
          for (std::size_t j = 0; j < stop; ++j) {
            Interval& x = elems[ids[j] / 2];
            const Interval now = x & col[j];
            if (now != x) narrow(v, ids[j], x, now);
          }
        }
        if (stop < c) {
          Interval& x = elems[ids[stop] / 2];
          if (!x.is_empty()) narrow(v, ids[stop], x, Interval::empty());
        }
      }
      if (stop < c) {
        params.set_empty();
        touch();
        return ids[stop];
      }
    }
  }
  touch();
  return kNoTimeAtom;
}

}  // namespace sillage::detail
