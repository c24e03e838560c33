#include "sillage/dynamics/ctc_heading.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "sillage/cn/tube_node.h"
#include "sillage/cn/tube_originals.h"
#include "sillage/ctc/shrink.h"
#include "sillage/dynamics/heading_common.h"
#include "sillage/error.h"
#include "sillage/interval/trig_batch.h"

namespace sillage {

CtcHeading::CtcHeading(double track) : track_(track) {
  if (!(track >= 0) || !std::isfinite(track)) {
    throw Error("CtcHeading: the track error must be finite and >= 0, got " + number_text(track));
  }
}

namespace {

// The rules of one contraction on (px, py, psi) given d and w, slice by
// slice, shared by the whole contraction and the local one (which applies
// them in the same order where the tubes changed). ix, iy: the steps I_k
// of the slices whose steps() were computed.
struct HeadingRules {
  HeadingRules(Tube& px_t, Tube& py_t, Tube& psi_t, const Tube& d_t, const Tube& w_t, double track_,
               detail::HeadingEmptyAt& at_)
      : px(px_t), py(py_t), psi(psi_t), d(d_t), w(w_t), td(*px_t.tdomain()), track(track_), at(at_) {
    for (const Tube* t : std::initializer_list<const Tube*>{&py_t, &psi_t, &d_t, &w_t}) {
      if (t->tdomain() != px_t.tdomain()) throw DimensionError("CtcHeading::contract: the tubes are not on one TDomain");
    }
    const std::size_t n = px_t.nb_slices();
    thread_local std::vector<Interval> ix_, iy_;  // scratch, per thread: a contraction does not nest
    ix_.resize(n), iy_.resize(n);
    ix = ix_.data(), iy = iy_.data();
  }

  // The steps of slices k0..k1: the directions of travel, their cosines and
  // sines by the batch rows, times the distances. False if a distance is empty.
  bool steps(std::size_t k0, std::size_t k1) {
    const std::size_t m = k1 - k0 + 1;
    const Interval tr = Interval(-1, 1) * Interval(track);
    for (std::size_t k = k0; k <= k1; ++k) ix[k] = psi.slices[k] + tr;
    detail::sin_rows(ix + k0, iy + k0, m);
    detail::cos_rows(ix + k0, ix + k0, m);
    for (std::size_t k = k0; k <= k1; ++k) {
      const Interval dk = d.data().slices[k] & Interval::pos_reals();
      if (dk.is_empty()) return false;  // d was given empty: the network names its first empty atom
      ix[k] = dk * ix[k], iy[k] = dk * iy[k];
    }
    return true;
  }
  // The forward rule of the positions on slice k; false (with `at`) when
  // empty. `moved`: whether gate k + 1 moved.
  bool forward(std::size_t k, bool& moved) {
    const Interval bx = px.gates[k + 1], by = py.gates[k + 1];
    if (!detail::narrow(px.gates[k + 1], px.gates[k] + ix[k])) return at = {0, 2 * (k + 1)}, false;
    if (!detail::narrow(py.gates[k + 1], py.gates[k] + iy[k])) return at = {1, 2 * (k + 1)}, false;
    moved = bx != px.gates[k + 1] || by != py.gates[k + 1];
    return true;
  }
  // The backward rule on slice k; `moved`: whether gate k moved.
  bool backward(std::size_t k, bool& moved) {
    const Interval bx = px.gates[k], by = py.gates[k];
    if (!detail::narrow(px.gates[k], px.gates[k + 1] - ix[k])) return at = {0, 2 * k}, false;
    if (!detail::narrow(py.gates[k], py.gates[k + 1] - iy[k])) return at = {1, 2 * k}, false;
    moved = bx != px.gates[k] || by != py.gates[k];
    return true;
  }
  // The heading on slice k from the displacement over it; false (with `at`)
  // when empty. `again` is set when its slice shrank by more than 1 %.
  bool heading(std::size_t k, bool& again) {
    const Interval dx = px.gates[k + 1] - px.gates[k], dy = py.gates[k + 1] - py.gates[k];
    if (dx.contains(0) && dy.contains(0)) return true;  // the displacement may be 0: no direction
    const Interval& wk = w.data().slices[k];
    if (wk.is_unbounded()) return true;  // any turn rate: no bound on the spread
    const Interval spread = td.slice_width(k) * Interval(wk.mag());
    if (!((spread + Interval(2 * track)).ub() < Interval::pi().lb())) return true;  // the directions may span a half turn
    const Interval r = detail::box_direction(dx, dy) + Interval(-1, 1) * (spread + Interval(track));
    const Interval before = psi.slices[k];
    const Interval kept = detail::periodic_meet(before, r);
    if (!detail::narrow(psi.slices[k], kept)) return at = {2, 2 * k + 1}, false;
    if (!detail::narrow(psi.gates[k], kept)) return at = {2, 2 * k}, false;
    if (!detail::narrow(psi.gates[k + 1], kept)) return at = {2, 2 * k + 2}, false;
    again = again || shrank(before, psi.slices[k], 0.01);
    return true;
  }

  detail::HeadingTube px, py, psi;
  const Tube& d;
  const Tube& w;
  const TDomain& td;
  double track;
  detail::HeadingEmptyAt& at;
  Interval* ix = nullptr;
  Interval* iy = nullptr;
};

// The whole contraction: per pass, the steps of every slice, the positions
// forward then backward, the heading of every slice; again while a heading
// shrank by more than 1 % (at most 5 passes).
bool contract_heading(Tube& px_t, Tube& py_t, Tube& psi_t, const Tube& d_t, const Tube& w_t, double track,
                      detail::HeadingEmptyAt& at) {
  HeadingRules h(px_t, py_t, psi_t, d_t, w_t, track, at);
  const std::size_t n = px_t.nb_slices();
  // An empty distance or turn rate anywhere: no trajectory.
  bool ok = !d_t.is_empty() && !w_t.is_empty();
  for (int pass = 0; pass < 5 && ok; ++pass) {
    ok = h.steps(0, n - 1);
    bool moved = false, again = false;
    for (std::size_t k = 0; k < n && ok; ++k) ok = h.forward(k, moved);
    for (std::size_t k = n; k-- > 0 && ok;) ok = h.backward(k, moved);
    for (std::size_t k = 0; k < n && ok; ++k) ok = h.heading(k, again);
    if (!again) break;
  }
  return detail::finish_heading(ok, px_t, py_t, psi_t);
}

// The local contraction (CtcHeading::contract_local): the whole one's rules
// in its order, each pass from the slices whose steps changed (first..last,
// then those whose heading shrank), the positions swept while their gates
// move, the headings of the slices next to a gate that moved.
bool contract_heading_local(Tube& px_t, Tube& py_t, Tube& psi_t, const Tube& d_t, const Tube& w_t, double track,
                            std::size_t first, std::size_t last, const TubeChanges (&changes)[3],
                            detail::HeadingEmptyAt& at) {
  HeadingRules h(px_t, py_t, psi_t, d_t, w_t, track, at);
  const std::size_t n = px_t.nb_slices();
  if (first > last || last >= n) {
    throw Error("CtcHeading::contract_local: slices " + std::to_string(first) + ".." + std::to_string(last) +
                " are not within the " + std::to_string(n) + " slices");
  }
  // The whole contraction's emptiness test on what may have changed.
  bool ok = true;
  for (const Tube* t : {&d_t, &w_t}) {
    for (std::size_t k = first; k <= last; ++k) ok = ok && !t->slice(k).is_empty() && !t->gate(k).is_empty();
    ok = ok && !t->gate(last + 1).is_empty();
  }
  // What the three tubes were where the rules went, to report what shrank.
  thread_local detail::TubeOriginals before[3];
  const detail::HeadingTube* tubes[3] = {&h.px, &h.py, &h.psi};
  for (std::size_t i = 0; i < 3; ++i) before[i].start(tubes[i]->slices, tubes[i]->gates), before[i].cover(first, last);
  const auto reach = [&](std::size_t k) {
    for (auto& o : before) o.reach(k, n);
  };
  // The slices whose steps are known, known_lo..known_hi (the sweeps reach
  // past them one slice at a time: a block that doubles is computed).
  std::size_t known_lo = first, known_hi = last;
  const auto know = [&](std::size_t k) {
    if (known_lo <= k && k <= known_hi) return true;
    const std::size_t span = std::max<std::size_t>(16, known_hi - known_lo + 1);
    const std::size_t a = k > known_hi ? known_hi + 1 : (known_lo > span ? known_lo - span : 0);
    const std::size_t b = k > known_hi ? std::min(n - 1, known_hi + span) : known_lo - 1;
    known_lo = std::min(known_lo, a), known_hi = std::max(known_hi, b);
    return h.steps(a, b);
  };
  // Per pass, the slices whose steps changed: what changed, then the slices whose heading shrank
  // (within the known ones, which the sweeps of the pass before went through).
  std::size_t lo = first, hi = last;
  for (int pass = 0; pass < 5 && ok; ++pass) {
    ok = h.steps(lo, hi);  // known: what changed, or where the sweeps of the pass before went
    bool moved = false, again = false;
    // Forward from lo, while a gate moves beyond hi; backward from there, while one moves below lo.
    std::size_t top = n - 1, bottom = 0;
    for (std::size_t k = lo; k < n && ok; ++k) {
      reach(k);
      ok = know(k) && h.forward(k, moved);
      if (ok && k > hi && !moved) {
        top = k;
        break;
      }
    }
    for (std::size_t k = top + 1; k-- > 0 && ok;) {
      reach(k);
      ok = know(k) && h.backward(k, moved);
      if (ok && k < lo && !moved) {
        bottom = k;
        break;
      }
    }
    // The headings of the slices next to a gate that moved, and of those that changed.
    std::size_t shrunk_lo = n, shrunk_hi = 0;
    for (std::size_t k = bottom; k <= top && ok; ++k) {
      const Interval s = h.psi.slices[k];  // covered: the sweeps went through k
      ok = h.heading(k, again);
      if (ok && s != h.psi.slices[k]) shrunk_lo = std::min(shrunk_lo, k), shrunk_hi = k;
    }
    if (!again || shrunk_lo > shrunk_hi) break;
    lo = shrunk_lo, hi = shrunk_hi;
  }
  if (ok) {
    for (std::size_t i = 0; i < 3; ++i) before[i].report(changes[i]);
  }
  return detail::finish_heading(ok, px_t, py_t, psi_t);
}

// cn.add(ctc, {px, py, psi, d, w}): the five tubes, whole, on one TDomain.
// After its first run it contracts from where its tubes changed.
class HeadingNode : public detail::HeadingNodeBase {
 public:
  HeadingNode(const CtcHeading& ctc, const std::vector<BoundDomain>& args)
      : HeadingNodeBase("CtcHeading", args, 5, "p (2 components), psi, d and w"), ctc_(ctc) {}
  bool run(NodeRun& r) const override {
    // The slices holding what woke it, over the five tubes.
    std::size_t first = 0, last = 0;
    bool any = false;
    for (std::size_t i = 0; i < 5 && !r.all; ++i) {
      std::size_t a = 0, b = 0;
      if (!dirty_slices(r, i, a, b)) continue;
      first = any ? std::min(first, a) : a, last = any ? std::max(last, b) : b;
      any = true;
    }
    if (!any) {
      return run_heading(r, [&](detail::HeadingEmptyAt& at) {
        return contract_heading(tube_arg(0), tube_arg(1), tube_arg(2), tube_arg(3), tube_arg(4), ctc_.track(), at);
      });
    }
    detail::HeadingEmptyAt at;
    const TubeChanges changed[3] = {changes(r, 0), changes(r, 1), changes(r, 2)};
    const bool ok = contract_heading_local(tube_arg(0), tube_arg(1), tube_arg(2), tube_arg(3), tube_arg(4),
                                           ctc_.track(), first, last, changed, at);
    if (!ok && at.atom != kNoAtom) r.empty_at = offset(at.tube) + at.atom;
    return ok;
  }

 private:
  CtcHeading ctc_;
};

}  // namespace

bool CtcHeading::contract(Tube& px, Tube& py, Tube& psi, const Tube& d, const Tube& w) const {
  detail::HeadingEmptyAt at;
  return contract_heading(px, py, psi, d, w, track_, at);
}

bool CtcHeading::contract(TubeVector& p, Tube& psi, const Tube& d, const Tube& w) const {
  if (p.size() != 2) {
    throw DimensionError("CtcHeading::contract: p must have 2 components, got " + std::to_string(p.size()));
  }
  return contract(p[0], p[1], psi, d, w);
}

bool CtcHeading::contract_local(Tube& px, Tube& py, Tube& psi, const Tube& d, const Tube& w, std::size_t first,
                                std::size_t last, const TubeChanges& px_changes, const TubeChanges& py_changes,
                                const TubeChanges& psi_changes) const {
  detail::HeadingEmptyAt at;
  const TubeChanges changed[3] = {px_changes, py_changes, psi_changes};
  return contract_heading_local(px, py, psi, d, w, track_, first, last, changed, at);
}

std::shared_ptr<const CnNode> CtcHeading::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<HeadingNode>(*this, args);
}

}  // namespace sillage
