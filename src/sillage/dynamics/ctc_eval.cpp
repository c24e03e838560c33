#include "sillage/dynamics/ctc_eval.h"

#include <string>
#include <vector>

#include "sillage/cn/tube_changes.h"
#include "sillage/dynamics/ctc_deriv.h"
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

// The gate fronts of (5.6); marks [glo, ghi] the gates it changed. False if a
// gate became empty.
bool sweep_fronts(const Interval& t, const Interval& z, Tube& y, const Tube& w, std::size_t& glo, std::size_t& ghi,
                  const TubeChanges& log) {
  const TDomain& td = *y.tdomain();
  const auto ts = td.times();
  const std::size_t n = td.nb_slices();
  TubeData& d = y.data();
  const auto& ws = w.data().slices;
  std::size_t first = 0, last = 0;
  slice_range(td, t, first, last, "CtcEval");
  const double ta = t.lb(), tb = t.ub();
  const auto in_t = [&](std::size_t i) { return ta <= ts[i] && ts[i] <= tb; };
  // Slice k holds times of [t] strictly inside it.
  const auto meets = [&](std::size_t k) { return ts[k] < tb && ts[k + 1] > ta; };
  const auto mark = [&](std::size_t i) {
    glo = std::min(glo, i);
    ghi = std::max(ghi, i);
  };
  // Sets gate g to h (h ⊆ g); false if it is empty.
  const auto narrow = [&](std::size_t i, const Interval& h) {
    Interval& g = d.gates[i];
    if (h == g) return true;
    log.gate(i, g, h);
    g = h;
    mark(i);
    return !g.is_empty();
  };

  // Forward: F encloses y(t_k) when t* <= t_k.
  std::vector<Interval> inside;  // F at the gates inside [t], in order
  Interval F = Interval::empty();
  for (std::size_t k = first; k <= n; ++k) {
    const Interval g = d.gates[k];
    if (in_t(k)) F |= g & z;
    F &= g;
    if (ts[k] > tb) {
      if (F == g && k > last + 1) break;  // the front holds the gate: nothing more to learn
      if (!narrow(k, F)) return false;
    } else if (in_t(k)) {
      inside.push_back(F);
    }
    if (k == n) break;
    const Interval dt = td.slice_width(k);
    Interval next = F + dt * ws[k];
    if (meets(k)) next |= (d.slices[k] & z) + Interval(0, dt.ub()) * ws[k];
    F = next;
  }

  // Backward: B encloses y(t_i) when t* >= t_i.
  Interval B = Interval::empty();
  std::size_t j = inside.size();
  for (std::size_t i = last + 1;; --i) {
    const Interval g = d.gates[i];
    if (in_t(i)) B |= g & z;
    B &= g;
    if (ts[i] < ta) {
      if (B == g && i + 1 < first) break;
      if (!narrow(i, B)) return false;
    } else if (in_t(i)) {
      if (!narrow(i, g & (inside[--j] | B))) return false;
    }
    if (i == 0) break;
    const std::size_t k = i - 1;
    const Interval dt = td.slice_width(k);
    Interval next = B - dt * ws[k];
    if (meets(k)) next |= (d.slices[k] & z) - Interval(0, dt.ub()) * ws[k];
    B = next;
  }
  return true;
}

// [t] ∩= [y]⁻¹([z]), [z] ∩= [y]([t]) (with the derivative when given).
bool contract_t_z(Interval& t, Interval& z, const Tube& y, const Tube* w) {
  t &= w ? y.inverse(z, *w, t) : y.inverse(z);
  if (t.is_empty()) return false;
  z &= w ? y.eval(t, *w) : y(t);
  return !z.is_empty();
}

// The gate at a degenerate t that is a time point: ∩= [z].
bool contract_gate(const Interval& t, const Interval& z, Tube& y, const TubeChanges& log) {
  if (!t.is_degenerate()) return true;
  const std::ptrdiff_t i = y.tdomain()->time_index(t.lb());
  if (i < 0) return true;
  Interval& g = y.data().gates[static_cast<std::size_t>(i)];
  const Interval h = g & z;
  if (h != g) {
    log.gate(static_cast<std::size_t>(i), g, h);
    g = h;
    y.touch();
  }
  return !h.is_empty();
}

bool contract_tube(const Interval& t, const Interval& z, Tube& y, const Tube& w, const TubeChanges& log) {
  std::size_t glo = y.nb_slices() + 1, ghi = 0;
  const bool ok = sweep_fronts(t, z, y, w, glo, ghi, log);
  if (glo <= ghi) y.touch();
  if (!ok) return false;
  if (glo > ghi) return true;
  // The slices around the changed gates, by CtcDeriv's slice rule.
  const std::size_t n = y.nb_slices(), a = glo > 0 ? glo - 1 : 0, b = std::min(ghi, n - 1);
  TubeData& d = y.data();
  std::vector<Interval> before;
  if (log.active()) {
    for (std::size_t k = a; k <= b; ++k) before.insert(before.end(), {d.gates[k], d.slices[k]});
    before.push_back(d.gates[b + 1]);
  }
  const bool deriv_ok = CtcDeriv().contract(y, w, a, b);
  if (log.active()) {
    for (std::size_t k = a; k <= b; ++k) {
      log.gate(k, before[2 * (k - a)], d.gates[k]);
      log.slice(k, before[2 * (k - a) + 1], d.slices[k]);
    }
    log.gate(b + 1, before.back(), d.gates[b + 1]);
  }
  return deriv_ok;
}

// Every case on component tubes (w empty: no derivative), one [t];
// logs[i] (if given) receives what shrank in y[i].
bool contract_all(Interval& t, IntervalVector& z, const std::vector<Tube*>& y, const std::vector<const Tube*>& w,
                  bool sampling, const char* where, const std::vector<TubeChanges>* logs) {
  if (y.empty() || z.size() != y.size() || (!w.empty() && w.size() != y.size()) || (logs && logs->size() != y.size())) {
    throw DimensionError(std::string(where) + ": z has " + std::to_string(z.size()) + " components, y " +
                         std::to_string(y.size()) + (w.empty() ? std::string() : ", w " + std::to_string(w.size())));
  }
  for (std::size_t i = 0; i < y.size(); ++i) {
    check_domains(*y[i], w.empty() ? nullptr : w[i], where);
    if (y[i]->tdomain() != y[0]->tdomain()) throw DimensionError(std::string(where) + ": y is on several TDomains");
  }
  bool ok = prepare_time(t, *y[0], sampling, where) && !z.is_empty();
  // [t] from every component first, then [z] and the tubes with the common [t].
  for (std::size_t i = 0; ok && i < y.size(); ++i) {
    t &= w.empty() ? y[i]->inverse(z[i]) : y[i]->inverse(z[i], *w[i], t);
    ok = !t.is_empty();
  }
  for (std::size_t i = 0; ok && i < y.size(); ++i) {
    const TubeChanges log = logs ? (*logs)[i] : TubeChanges();
    ok = contract_t_z(t, z[i], *y[i], w.empty() ? nullptr : w[i]);
    if (ok) ok = w.empty() ? contract_gate(t, z[i], *y[i], log) : contract_tube(t, z[i], *y[i], *w[i], log);
  }
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
  return make_eval_node(*this, args);
}

bool CtcEval::contract(Interval& t, Interval& z, Tube& y, const Tube& w) const {
  IntervalVector zv{z};
  const bool ok = contract_all(t, zv, {&y}, {&w}, sampling_, "CtcEval::contract(t, z, y, w)", nullptr);
  z = ok ? zv[0] : Interval::empty();
  return ok;
}

bool CtcEval::contract(Interval& t, Interval& z, Tube& y) const {
  IntervalVector zv{z};
  const bool ok = contract_all(t, zv, {&y}, {}, sampling_, "CtcEval::contract(t, z, y)", nullptr);
  z = ok ? zv[0] : Interval::empty();
  return ok;
}

bool CtcEval::contract(Interval& t, IntervalVector& z, TubeVector& y, const TubeVector& w) const {
  return contract_all(t, z, pointers<TubeVector, Tube>(y), pointers<const TubeVector, const Tube>(w), sampling_,
                      "CtcEval::contract(t, z, y, w)", nullptr);
}

bool CtcEval::contract(Interval& t, IntervalVector& z, TubeVector& y) const {
  return contract_all(t, z, pointers<TubeVector, Tube>(y), {}, sampling_, "CtcEval::contract(t, z, y)", nullptr);
}

bool CtcEval::contract(Interval& t, IntervalVector& z, const std::vector<Tube*>& y, const std::vector<const Tube*>& w,
                       const std::vector<TubeChanges>& changes) const {
  return contract_all(t, z, y, w, sampling_, "CtcEval::contract(t, z, y, w, changes)", &changes);
}

bool CtcEval::contract(Interval& t, IntervalVector& z, const std::vector<Tube*>& y, const std::vector<const Tube*>& w,
                       double ratio, std::vector<std::vector<std::size_t>>& changed) const {
  changed.assign(y.size(), {});
  std::vector<TubeChanges> logs;
  for (auto& c : changed) logs.emplace_back(c, 0, ratio);
  return contract_all(t, z, y, w, sampling_, "CtcEval::contract(t, z, y, w, ratio, changed)", &logs);
}

}  // namespace sillage
