#include "sillage/dynamics/ctc_heading.h"

#include <cmath>
#include <initializer_list>

#include "sillage/cn/tube_node.h"
#include "sillage/ctc/shrink.h"
#include "sillage/error.h"
#include "sillage/interval/elementary.h"

namespace sillage {

namespace {

// Where a contraction found no trajectory: the tube (0: px, 1: py, 2: psi) and its atom.
struct EmptyAt {
  std::size_t tube = 0, atom = kNoAtom;
};

// The directions of the box (dx, dy), which does not hold 0: the narrower of
// atan2 (cut on the negative x axis) and atan2 of the opposite box plus π
// (cut on the positive x axis).
Interval direction(const Interval& dx, const Interval& dy) {
  const Interval a = atan2(dy, dx), b = atan2(-dy, -dx) + Interval::pi();
  return a.diam() <= b.diam() ? a : b;
}

// s ∩ (r + 2πZ), hulled; s bounded and not too wide (else s unchanged).
Interval periodic_meet(const Interval& s, const Interval& r) {
  if (s.is_unbounded() || r.is_unbounded() || s.diam() > 1e6) return s;
  const Interval period = Interval::two_pi();
  const auto shifted = [&](double n) { return (r + period * Interval(n)) & s; };
  double lo = std::floor((s.lb() - r.ub()) / (2 * M_PI)) - 1, hi = std::ceil((s.ub() - r.lb()) / (2 * M_PI)) + 1;
  while (lo <= hi && shifted(lo).is_empty()) ++lo;
  while (hi >= lo && shifted(hi).is_empty()) --hi;
  if (lo > hi) return Interval::empty();
  return shifted(lo) | shifted(hi);
}

bool narrow(Interval& x, const Interval& y) {
  x &= y;
  return !x.is_empty();
}

// One forward and backward sweep of the positions; false with `at` when empty.
bool sweep_positions(TubeData& px, TubeData& py, const std::vector<Interval>& ix, const std::vector<Interval>& iy,
                     EmptyAt& at) {
  const std::size_t n = ix.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (!narrow(px.gates[k + 1], px.gates[k] + ix[k])) return at = {0, 2 * (k + 1)}, false;
    if (!narrow(py.gates[k + 1], py.gates[k] + iy[k])) return at = {1, 2 * (k + 1)}, false;
  }
  for (std::size_t k = n; k-- > 0;) {
    if (!narrow(px.gates[k], px.gates[k + 1] - ix[k])) return at = {0, 2 * k}, false;
    if (!narrow(py.gates[k], py.gates[k + 1] - iy[k])) return at = {1, 2 * k}, false;
  }
  return true;
}

}  // namespace

CtcHeading::CtcHeading(double track) : track_(track) {
  if (!(track >= 0) || !std::isfinite(track)) {
    throw Error("CtcHeading: the track error must be finite and >= 0, got " + std::to_string(track));
  }
}

namespace {

bool contract_heading(Tube& px_t, Tube& py_t, Tube& psi_t, const Tube& d_t, const Tube& w_t, double track,
                      EmptyAt& at) {
  const auto td = px_t.tdomain();
  for (const Tube* t : std::initializer_list<const Tube*>{&py_t, &psi_t, &d_t, &w_t}) {
    if (t->tdomain() != td) throw DimensionError("CtcHeading::contract: the tubes are not on one TDomain");
  }
  const std::size_t n = px_t.nb_slices();
  // An empty distance or turn rate anywhere: no trajectory.
  bool ok = !d_t.is_empty() && !w_t.is_empty();
  TubeData &px = px_t.data(), &py = py_t.data(), &psi = psi_t.data();
  const Interval tr = Interval(-1, 1) * Interval(track);
  const Interval pi = Interval::pi();
  std::vector<Interval> ix(n), iy(n);
  for (int pass = 0; pass < 5 && ok; ++pass) {
    for (std::size_t k = 0; k < n && ok; ++k) {
      const Interval dk = d_t.data().slices[k] & Interval::pos_reals();
      if (dk.is_empty()) ok = false;  // d was given empty: the network names its first empty atom
      const Interval dir = psi.slices[k] + tr;
      ix[k] = dk * cos(dir), iy[k] = dk * sin(dir);
    }
    ok = ok && sweep_positions(px, py, ix, iy, at);
    bool again = false;
    for (std::size_t k = 0; k < n && ok; ++k) {
      const Interval dx = px.gates[k + 1] - px.gates[k], dy = py.gates[k + 1] - py.gates[k];
      if (dx.contains(0) && dy.contains(0)) continue;  // the displacement may be 0: no direction
      const Interval& wk = w_t.data().slices[k];
      if (wk.is_unbounded()) continue;  // any turn rate: no bound on the spread
      const Interval spread = td->slice_width(k) * Interval(wk.mag());
      if (!((spread + Interval(2 * track)).ub() < pi.lb())) continue;  // the directions may span a half turn
      const Interval r = direction(dx, dy) + Interval(-1, 1) * (spread + Interval(track));
      const Interval before = psi.slices[k];
      const Interval kept = periodic_meet(before, r);
      if (!narrow(psi.slices[k], kept)) at = {2, 2 * k + 1}, ok = false;
      else if (!narrow(psi.gates[k], kept)) at = {2, 2 * k}, ok = false;
      else if (!narrow(psi.gates[k + 1], kept)) at = {2, 2 * k + 2}, ok = false;
      again = again || shrank(before, psi.slices[k], 0.01);
    }
    if (!again) break;
  }
  if (!ok) {
    px_t.set(Interval::empty()), py_t.set(Interval::empty()), psi_t.set(Interval::empty());
    return false;
  }
  px_t.touch(), py_t.touch(), psi_t.touch();
  return true;
}

// cn.add(ctc, {px, py, psi, d, w}): the five tubes, whole, on one TDomain.
class HeadingNode : public TubeNode {
 public:
  HeadingNode(const CtcHeading& ctc, const std::vector<BoundDomain>& args) : TubeNode("CtcHeading", args), ctc_(ctc) {
    if (args.size() != 5) {
      throw DimensionError(where() + ": expects p (2 components), psi, d and w, got " + std::to_string(args.size()) +
                           " tubes");
    }
    t_ = whole_tubes(0, 5, "p, psi, d and w");
  }
  bool run(NodeRun& r) const override {
    thread_local TubeSnapshot before[3];  // scratch: per thread, never shared by two runs
    for (std::size_t i = 0; i < 3; ++i) before[i].take(t_[i]->tube());
    EmptyAt at;
    const bool ok = contract_heading(t_[0]->tube(), t_[1]->tube(), t_[2]->tube(), t_[3]->tube(), t_[4]->tube(),
                                     ctc_.track(), at);
    for (std::size_t i = 0; i < 3; ++i) changes(r, i).diff(before[i], t_[i]->tube());
    if (!ok && at.atom != kNoAtom) r.empty_at = offset(at.tube) + at.atom;
    return ok;
  }

 private:
  CtcHeading ctc_;
  std::vector<std::shared_ptr<TubeDomain>> t_;
};

}  // namespace

bool CtcHeading::contract(Tube& px, Tube& py, Tube& psi, const Tube& d, const Tube& w) const {
  EmptyAt at;
  return contract_heading(px, py, psi, d, w, track_, at);
}

bool CtcHeading::contract(TubeVector& p, Tube& psi, const Tube& d, const Tube& w) const {
  if (p.size() != 2) {
    throw DimensionError("CtcHeading::contract: p must have 2 components, got " + std::to_string(p.size()));
  }
  const bool ok = contract(p[0], p[1], psi, d, w);
  return ok;
}

std::shared_ptr<const CnNode> CtcHeading::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<HeadingNode>(*this, args);
}

}  // namespace sillage
