#include "sillage/dynamics/ctc_eval.h"

#include <algorithm>
#include <cstdint>

#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "sillage/cn/tube_changes.h"
#include "sillage/cn/tube_domain.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/slice_rule_x4.h"
#include "sillage/interval/arith_rows.h"
#include "sillage/tube/eval_in_slice.h"
#include "sillage/tube/slice_deriv.h"
#include "sillage/dynamics/tube_nodes.h"
#include "sillage/error.h"

namespace sillage {

namespace {

void check_domains(const Tube& y, const Tube* w, const char* where) {
  if (w && w->tdomain() != y.tdomain()) {
    throw DimensionError(std::string(where) + ": y and w are not on one TDomain");
  }
}

// [t] ∩= [t_0, t_N] (Error if they do not meet), then samples the TDomain at
// a degenerate t when allowed. False if t is empty.
bool prepare_time(Interval& t, const Tube& y, bool sampling, const char* where) {
  if (t.is_empty()) return false;
  const Interval dom = y.tdomain()->t0_tf();
  if (!t.intersects(dom)) {
    throw Error(std::string(where) + ": [t] = " + t.str() + " does not meet the time domain " + dom.str());
  }
  t &= dom;
  if (sampling && t.is_degenerate() && !y.tdomain()->is_time_point(t.lb())) y.tdomain()->sample(t.lb());
  return true;
}

// The slices meeting the input [t]: the part of the tube the observation
// teaches directly (gates first .. last+1, slices first .. last).
struct Region {
  std::size_t first = 0, last = 0;
};

// A tube being written, through its caller's Tube::Writer (the caller knows
// whether it changed, and says so when the writer ends): its TDomain, and its
// slices and gates in place.
struct Written {
  Written(const Tube& y, const Tube::Writer& w) : tube(y), slices(w.slices()), gates(w.gates()) {}
  const Tube& tube;
  std::span<Interval> slices, gates;
};

// Narrows gate i to h (h ⊆ the gate); false if it is now empty.
bool narrow_gate(const Written& d, std::size_t i, const Interval& h, bool& changed) {
  Interval& g = d.gates[i];
  if (h == g) return !g.is_empty();
  g = h;
  changed = true;
  return !g.is_empty();
}

// The gate fronts of (5.6) over the region, for t1 ∈ [t]:
//   F(t_i) ⊇ y(t_i) for t1 <= t_i,  B(t_i) ⊇ y(t_i) for t1 >= t_i.
// Across slice k a front moves by δ[w](k) and gains, when [t] meets the
// slice on [c1, c2], the values through the part of [t] inside it:
//   forward  ([y]([c1, c2]) ∩ [z]) + [t_{k+1} - c2, t_{k+1} - c1]·[w](k),
//   backward ([y]([c1, c2]) ∩ [z]) - [c1 - t_k, c2 - t_k]·[w](k),
// where [y]([c1, c2]) is the polygon of the slice over [c1, c2] when [t]
// covers only a part of it (Tube::eval with the derivative), so that [t] is
// never rounded out to whole slices. A gate after [t] is narrowed to F, one
// before to B, one inside to F ∪ B. False if a gate became empty.
// The buffers of sweep_region, reused from call to call.
struct SweepBuffers {
  std::vector<Interval> part, hull, front, step;
};

bool sweep_region(const Interval& t, const Interval& z, const Written& d, const Tube& w, Region r, bool& changed,
                  SweepBuffers& buf) {
  const TDomain& td = *d.tube.tdomain();
  const auto ts = td.times();
  const auto& ws = w.data().slices;
  const double ta = t.lb(), tb = t.ub();
  const auto in_t = [&](std::size_t i) { return ta <= ts[i] && ts[i] <= tb; };
  const std::size_t m = r.last - r.first + 1;
  // Per slice of the region: the times of [t] in it and the hull there.
  auto& part = buf.part;
  auto& hull = buf.hull;
  auto& front = buf.front;
  auto& step = buf.step;  // δ[w](k), read by both fronts
  part.assign(m, Interval::empty());
  hull.assign(m, Interval::empty());
  step.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t k = r.first + j;
    step[j] = td.slice_width(k) * ws[k];
    if (!(ts[k] < tb && ts[k + 1] > ta)) continue;  // no time of [t] strictly inside
    part[j] = Interval::from_bounds_unchecked(std::max(ta, ts[k]), std::min(tb, ts[k + 1]));  // [t] ∩ slice k
    const bool whole = part[j].lb() == ts[k] && part[j].ub() == ts[k + 1];
    const TubeData& y = d.tube.data();  // the same storage, read
    hull[j] = (whole ? d.slices[k] : detail::eval_in_slice(y, w.data(), ts, k, part[j].lb(), part[j].ub()) & d.slices[k]) &
              z;
  }
  front.assign(m + 1, Interval::empty());
  Interval F = Interval::empty();
  for (std::size_t j = 0;; ++j) {
    const std::size_t k = r.first + j;
    if (in_t(k)) F |= d.gates[k] & z;
    F &= d.gates[k];
    front[j] = F;
    if (j == m) break;
    F = F + step[j];
    if (!hull[j].is_empty()) F |= hull[j] + (Interval(ts[k + 1]) - part[j]) * ws[k];
  }
  Interval B = Interval::empty();
  for (std::size_t j = m;; --j) {
    const std::size_t i = r.first + j;
    if (in_t(i)) B |= d.gates[i] & z;
    B &= d.gates[i];
    const Interval h = ts[i] > tb ? front[j] : ts[i] < ta ? B : (front[j] | B);
    if (!narrow_gate(d, i, d.gates[i] & h, changed)) return false;
    if (j == 0) break;
    const std::size_t k = i - 1;
    B = B - step[j - 1];
    if (!hull[j - 1].is_empty()) B |= hull[j - 1] - (part[j - 1] - Interval(ts[k])) * ws[k];
  }
  return true;
}

// x ∩= [lo, hi] on raw bounds; tell(before, after) logs a change. False if x is now empty.
template <class Tell>
bool narrow_bounds(Interval& x, double lo, double hi, bool& changed, Tell tell) {
  lo = std::max(lo, x.lb());
  hi = std::min(hi, x.ub());
  if (!(lo <= hi)) return false;
  if (lo != x.lb() || hi != x.ub()) {
    const Interval h = Interval::from_bounds_unchecked(lo, hi);
    tell(x, h);
    x = h;
    changed = true;
  }
  return true;
}

// Gate i ∩= [lo, hi] on raw bounds, logged; false if it is now empty.
bool narrow_raw(const Written& d, std::size_t i, double lo, double hi, bool& changed, const TubeChanges& log) {
  return narrow_bounds(d.gates[i], lo, hi, changed, [&](const Interval& x, const Interval& h) { log.gate(i, x, h); });
}

// Beyond the region the fronts go on while they shrink gates. Past the first
// gate a front leaves as it was, the front encloses what CtcDeriv carries
// forward (backward) from that gate, so going further would only repeat
// CtcDeriv: standalone calls run it over the whole tube after this (and are
// monotone, whatever the input), other callers leave it to their network.
// The gates the outward sweeps changed: [lo, r.first) and (r.last + 1, hi].
struct Reached {
  std::size_t lo = 0, hi = 0;
};

// δ[v] of the slices a front crosses, computed ahead by blocks (scale_slices:
// 4 at a time with AVX2 on the portable path, the same bits as one at a time).
template <class R>
class FrontScale {
 public:
  FrontScale(std::span<const double> ts, std::span<const Interval> ws) : ts_(ts), ws_(ws) {}
  // δ[v] of slice k; `forward`: the front goes on to k + 1 next, else to k - 1.
  void get(std::size_t k, bool forward, double& plo, double& phi) {
    if (k < first_ || k >= first_ + count_) {
      const std::size_t n = ws_.size();
      first_ = forward ? k : (k + 1 >= kAhead ? k + 1 - kAhead : 0);
      count_ = std::min(kAhead, n - first_);
      detail::scale_slices<R>(ts_.data(), ws_.data(), first_, count_, lo_, hi_);
    }
    plo = lo_[k - first_];
    phi = hi_[k - first_];
  }

 private:
  static constexpr std::size_t kAhead = 8;  // most fronts stop within a few slices
  std::span<const double> ts_;
  std::span<const Interval> ws_;
  std::size_t first_ = 0, count_ = 0;
  double lo_[kAhead], hi_[kAhead];
};

// Outside the region the fronts only move: F forward from the last gate of
// the region, B backward from its first gate. On raw bounds with the
// rounding policy of CtcDeriv. False if a gate or a slice of [w] is empty.
template <class R>
bool sweep_outward(const Written& d, const Tube& w, Region r, bool& changed, Reached& out,
                   const TubeChanges& log) {
  const auto ts = d.tube.tdomain()->times();
  const auto& ws = w.data().slices;
  const std::size_t n = ts.size() - 1;
  out = {r.first, r.last + 1};
  FrontScale<R> scaled(ts, ws);
  for (std::size_t k = r.last + 1; k < n; ++k) {
    const Interval &a = d.gates[k], &v = ws[k];
    if (v.is_empty()) return false;
    double plo, phi;
    scaled.get(k, true, plo, phi);
    bool moved = false;
    if (!narrow_raw(d, k + 1, R::add_down(a.lb(), plo), R::add_up(a.ub(), phi), moved, log)) return false;
    if (moved) out.hi = k + 1, changed = true;
    else break;
  }
  for (std::size_t i = r.first; i > 0; --i) {
    const Interval &b = d.gates[i], &v = ws[i - 1];
    if (v.is_empty()) return false;
    double plo, phi;
    scaled.get(i - 1, false, plo, phi);
    bool moved = false;
    if (!narrow_raw(d, i - 1, R::sub_down(b.lb(), phi), R::sub_up(b.ub(), plo), moved, log)) return false;
    if (moved) out.lo = i - 1, changed = true;
    else break;
  }
  return true;
}

// Slices a .. b ∩= the hull of their polygon (CtcDeriv's slice rule) from
// their gates as they are: the gates are not changed, so that the result does
// not depend on the order of the slices. Logged. False if something is empty.
template <class R>
bool hull_slices(const Written& d, const Tube& w, std::size_t a, std::size_t b, bool& changed,
                 const TubeChanges& log = TubeChanges()) {
  const auto ts = d.tube.tdomain()->times();
  const auto& ws = w.data().slices;
  // By blocks: on the portable path with AVX2 the hulls of a block are
  // computed 4 at a time first (the same bits), its tail one at a time.
  constexpr std::size_t kBlock = 64;
  double block_lo[kBlock], block_up[kBlock];
  for (std::size_t first = a; first <= b; first += kBlock) {
    const std::size_t end = std::min(b + 1, first + kBlock);
    std::size_t wide = 0;  // slices first .. first+wide-1 are in block_lo, block_up
    if constexpr (std::is_same_v<R, detail::SoftRounding>) {
      if (detail::avx2_rows()) {
        wide = (end - first) / 4 * 4;
        detail::polygon_hull_bounds_x4(ts.data(), d.gates.data(), ws.data(), first, wide, block_lo, block_up);
      }
    }
    for (std::size_t k = first; k < end; ++k) {
      const Interval &ga = d.gates[k], &gb = d.gates[k + 1], &v = ws[k];
      Interval& s = d.slices[k];
      if (ga.is_empty() || gb.is_empty() || v.is_empty() || s.is_empty()) return false;
      double lo, up;
      if (k - first < wide) {
        lo = block_lo[k - first];
        up = block_up[k - first];
      } else {
        double plo, phi;
        detail::scale<R>(v.lb(), v.ub(), detail::width<R>(ts[k], ts[k + 1]), plo, phi);
        detail::polygon_hull<R, false>(ga.lb(), ga.ub(), gb.lb(), gb.ub(), v.lb(), v.ub(), plo, phi,
                                      detail::straddles(v.lb(), v.ub()), lo, up);
      }
      if (!narrow_bounds(s, lo, up, changed, [&](const Interval& x, const Interval& h) { log.slice(k, x, h); }))
        return false;
    }
  }
  return true;
}

// The fronts outside the region, and the slices next to the gates they changed.
bool outward(const Written& y, const Tube& w, Region r, bool& changed, const TubeChanges& log = TubeChanges()) {
  const std::size_t n = y.slices.size();
  return detail::with_policy([&]<class R>() {
    Reached g;
    if (!sweep_outward<R>(y, w, r, changed, g, log)) return false;
    const std::size_t lo = g.lo > 0 ? g.lo - 1 : 0, hi = std::min(g.hi, n - 1);
    if (r.first > lo && !hull_slices<R>(y, w, lo, r.first - 1, changed, log)) return false;
    return r.last + 1 > hi || hull_slices<R>(y, w, r.last + 1, hi, changed, log);
  });
}

// [t] ∩= [y]⁻¹([z]) (when `invert`), [z] ∩= [y]([t]) (with the derivative when given).
bool contract_t_z(Interval& t, Interval& z, const Tube& y, const Tube* w, bool invert) {
  if (invert) t &= w ? y.inverse(z, *w, t) : y.inverse(z);
  if (t.is_empty()) return false;
  z &= w ? y.eval(t, *w) : y(t);
  return !z.is_empty();
}

// The gate at a degenerate t that is a time point: ∩= [z].
bool contract_gate(const Interval& t, const Interval& z, const Written& y, bool& changed) {
  if (!t.is_degenerate()) return true;
  const std::ptrdiff_t i = y.tube.tdomain()->time_index(t.lb());
  if (i < 0) return true;
  return narrow_gate(y, static_cast<std::size_t>(i), y.gates[static_cast<std::size_t>(i)] & z, changed);
}

// What the region held before, to report what shrank over the whole call
// (several passes may each shrink an atom a little).
struct RegionSnapshot {
  std::vector<Interval> gates, slices;
  void take(const Tube& y, Region r) {
    const TubeData& d = y.data();
    gates.assign(d.gates.begin() + static_cast<std::ptrdiff_t>(r.first),
                 d.gates.begin() + static_cast<std::ptrdiff_t>(r.last + 2));
    slices.assign(d.slices.begin() + static_cast<std::ptrdiff_t>(r.first),
                  d.slices.begin() + static_cast<std::ptrdiff_t>(r.last + 1));
  }
  void report(const Tube& y, Region r, const TubeChanges& log) const {
    const TubeData& d = y.data();
    for (std::size_t j = 0; j < gates.size(); ++j) log.gate(r.first + j, gates[j], d.gates[r.first + j]);
    for (std::size_t j = 0; j < slices.size(); ++j) log.slice(r.first + j, slices[j], d.slices[r.first + j]);
  }
};

// What contract_all needs from call to call, per thread: a network calls it
// tens of thousands of times, and would otherwise allocate these each time.
struct EvalScratch {
  std::vector<RegionSnapshot> before;
  IntervalVector z0 = IntervalVector(1);
  SweepBuffers sweep;
  std::vector<Interval> given;
};

// Passes over [t], [z] and the region until none changes anything, so that
// one call is a fixed point (a network does not wake a contractor on its own
// changes). Bounded, as a guard: each pass that goes on shrinks a bound.
constexpr int kMaxPasses = 200;

// Every case on component tubes (w empty: no derivative), one [t].
// Beyond the region the fronts go on while they shrink gates, and the slices
// next to those gates are hulled. Standalone calls (whole_tube) then run
// CtcDeriv over the whole tube, inside the passes (so that one call stays its
// own fixed point; CtcDeriv also reads the gates of [w], and says empty when
// one is). Other callers (network nodes, CtcT1T2, CtcQEval) leave that to
// their network; their logs[i] receive what shrank in y[i].
bool contract_all(Interval& t, IntervalVector& z, const std::vector<Tube*>& y, const std::vector<const Tube*>& w,
                  bool sampling, bool whole_tube, const char* where, const std::vector<TubeChanges>* logs,
                  bool beyond = true, bool one_pass = false) {
  if (y.empty() || z.size() != y.size() || (!w.empty() && w.size() != y.size()) || (logs && logs->size() != y.size())) {
    throw DimensionError(std::string(where) + ": z has " + std::to_string(z.size()) + " components, y " +
                         std::to_string(y.size()) + (w.empty() ? std::string() : ", w " + std::to_string(w.size())));
  }
  for (std::size_t i = 0; i < y.size(); ++i) {
    check_domains(*y[i], w.empty() ? nullptr : w[i], where);
    if (y[i]->tdomain() != y[0]->tdomain()) throw DimensionError(std::string(where) + ": y is on several TDomains");
  }
  bool ok = prepare_time(t, *y[0], sampling, where) && !z.is_empty();
  Region r;
  if (ok) slice_range(*y[0]->tdomain(), t, r.first, r.last, where);
  thread_local EvalScratch scratch;
  auto& before = scratch.before;
  const std::size_t nb_before = logs ? y.size() : 0;
  if (before.size() < nb_before) before.resize(nb_before);
  for (std::size_t i = 0; ok && i < nb_before; ++i) before[i].take(*y[i], r);
  bool deriv_fresh = false;
  for (int pass = 0; ok && pass < kMaxPasses; ++pass) {
    const Interval t0 = t;
    IntervalVector& z0 = scratch.z0;
    z0 = z;
    bool changed = false;
    // [t] from every component first, then [z] and the tubes with the common [t].
    // given[i]: [t] as component i's inverse left it. The inverse is idempotent
    // (it hulls, within [t], the times of each slice whose polygon meets z), so
    // while [t] is still that, the second inverse would give it again.
    auto& given = scratch.given;
    given.resize(y.size());
    for (std::size_t i = 0; ok && i < y.size(); ++i) {
      t &= w.empty() ? y[i]->inverse(z[i]) : y[i]->inverse(z[i], *w[i], t);
      ok = !t.is_empty();
      given[i] = t;
    }
    for (std::size_t i = 0; ok && i < y.size(); ++i) {
      bool moved = false;
      ok = contract_t_z(t, z[i], *y[i], w.empty() ? nullptr : w[i], t != given[i]);
      Tube::Writer yw = y[i]->write();
      const Written yi(*y[i], yw);
      if (ok && w.empty()) ok = contract_gate(t, z[i], yi, moved);
      if (ok && !w.empty()) ok = sweep_region(t, z[i], yi, *w[i], r, moved, scratch.sweep);
      if (ok && !w.empty()) {
        ok = detail::with_policy([&]<class R>() { return hull_slices<R>(yi, *w[i], r.first, r.last, moved); });
      }
      yw.commit(moved);
      changed = changed || moved;
    }
    if (changed || t != t0 || z != z0) {
      deriv_fresh = false;
      if (one_pass) break;
      continue;
    }
    // The region is at its fixed point: the fronts beyond it and CtcDeriv
    // over the whole tube (once more only if they shrank something).
    if (!whole_tube || w.empty() || deriv_fresh) break;
    deriv_fresh = true;
    bool moved_any = false;
    for (std::size_t i = 0; ok && i < y.size(); ++i) {
      bool moved = false;
      {
        Tube::Writer yw = y[i]->write();
        ok = outward(Written(*y[i], yw), *w[i], r, moved);
        yw.commit(moved);
      }
      if (ok) {
        const std::uint64_t v0 = y[i]->version();  // CtcDeriv touches y when it shrinks it
        ok = CtcDeriv().contract(*y[i], *w[i]);
        if (ok && y[i]->version() != v0) moved = true;
      }
      moved_any = moved_any || moved;
    }
    if (!moved_any) break;
  }
  // Other callers: the fronts beyond the region as long as they shrink gates
  // (unless the caller's network runs CtcDeriv on y and w, which does it).
  for (std::size_t i = 0; ok && beyond && !whole_tube && !w.empty() && i < y.size(); ++i) {
    bool moved = false;
    Tube::Writer yw = y[i]->write();
    ok = outward(Written(*y[i], yw), *w[i], r, moved, logs ? (*logs)[i] : TubeChanges());
    yw.commit(moved);
  }
  for (std::size_t i = 0; ok && i < nb_before; ++i) before[i].report(*y[i], r, (*logs)[i]);
  if (!ok) {
    t.set_empty();
    z.set_empty();
    for (Tube* yi : y) yi->set(Interval::empty());
  }
  return ok;
}

template <class V, class T>
std::vector<T*> pointers(V& y) {
  std::vector<T*> p;
  for (std::size_t i = 0; i < y.size(); ++i) p.push_back(&y[i]);
  return p;
}

}  // namespace

std::shared_ptr<const CnNode> CtcEval::make_node(const std::vector<BoundDomain>& args) const {
  return detail::make_eval_node(*this, args);
}

NetworkCtc::Gates CtcEval::gates_for(const std::vector<DomainRef>& args) const {
  if (!gates_at_bounds_ || args.size() < 3) return {};
  const Interval t = args[0].domain()->atom(args[0].first());
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (const auto* y = dynamic_cast<const TubeDomain*>(args[i].domain().get())) {
      if (t.is_empty()) return {};
      return {y->tube().tdomain(), {t.lb(), t.ub()}};
    }
  }
  return {};
}

bool CtcEval::contract(Interval& t, Interval& z, Tube& y, const Tube& w) const {
  IntervalVector zv{z};
  const bool ok = contract_all(t, zv, {&y}, {&w}, sampling_, true, "CtcEval::contract(t, z, y, w)", nullptr);
  z = ok ? zv[0] : Interval::empty();
  return ok;
}

bool CtcEval::contract(Interval& t, Interval& z, Tube& y) const {
  IntervalVector zv{z};
  const bool ok = contract_all(t, zv, {&y}, {}, sampling_, true, "CtcEval::contract(t, z, y)", nullptr);
  z = ok ? zv[0] : Interval::empty();
  return ok;
}

bool CtcEval::contract(Interval& t, IntervalVector& z, TubeVector& y, const TubeVector& w) const {
  return contract_all(t, z, pointers<TubeVector, Tube>(y), pointers<const TubeVector, const Tube>(w), sampling_, true,
                      "CtcEval::contract(t, z, y, w)", nullptr);
}

bool CtcEval::contract(Interval& t, IntervalVector& z, TubeVector& y) const {
  return contract_all(t, z, pointers<TubeVector, Tube>(y), {}, sampling_, true, "CtcEval::contract(t, z, y)", nullptr);
}

bool CtcEval::contract(Interval& t, IntervalVector& z, const std::vector<Tube*>& y, const std::vector<const Tube*>& w,
                       const std::vector<TubeChanges>& changes, bool beyond, bool one_pass) const {
  return contract_all(t, z, y, w, sampling_, false, "CtcEval::contract(t, z, y, w, changes)", &changes, beyond,
                      one_pass);
}

bool CtcEval::contract(Interval& t, IntervalVector& z, const std::vector<Tube*>& y, const std::vector<const Tube*>& w,
                       double ratio, std::vector<std::vector<std::size_t>>& changed) const {
  changed.assign(y.size(), {});
  std::vector<TubeChanges> logs;
  for (auto& c : changed) logs.emplace_back(c, 0, ratio);
  return contract_all(t, z, y, w, sampling_, false, "CtcEval::contract(t, z, y, w, ratio, changed)", &logs);
}

}  // namespace sillage
