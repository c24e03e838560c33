#include "sillage/dynamics/ctc_heading.h"

#include <cmath>
#include <initializer_list>

#include "sillage/cn/tube_node.h"
#include "sillage/ctc/shrink.h"
#include "sillage/dynamics/heading_common.h"
#include "sillage/error.h"
#include "sillage/interval/trig_batch.h"

namespace sillage {

namespace {

// One forward and backward sweep of the positions; false with `at` when empty.
bool sweep_positions(const detail::HeadingTube& px, const detail::HeadingTube& py, const std::vector<Interval>& ix,
                     const std::vector<Interval>& iy, detail::HeadingEmptyAt& at) {
  const std::size_t n = ix.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (!detail::narrow(px.gates[k + 1], px.gates[k] + ix[k])) return at = {0, 2 * (k + 1)}, false;
    if (!detail::narrow(py.gates[k + 1], py.gates[k] + iy[k])) return at = {1, 2 * (k + 1)}, false;
  }
  for (std::size_t k = n; k-- > 0;) {
    if (!detail::narrow(px.gates[k], px.gates[k + 1] - ix[k])) return at = {0, 2 * k}, false;
    if (!detail::narrow(py.gates[k], py.gates[k + 1] - iy[k])) return at = {1, 2 * k}, false;
  }
  return true;
}

}  // namespace

CtcHeading::CtcHeading(double track) : track_(track) {
  if (!(track >= 0) || !std::isfinite(track)) {
    throw Error("CtcHeading: the track error must be finite and >= 0, got " + number_text(track));
  }
}

namespace {

bool contract_heading(Tube& px_t, Tube& py_t, Tube& psi_t, const Tube& d_t, const Tube& w_t, double track,
                      detail::HeadingEmptyAt& at) {
  const auto td = px_t.tdomain();
  for (const Tube* t : std::initializer_list<const Tube*>{&py_t, &psi_t, &d_t, &w_t}) {
    if (t->tdomain() != td) throw DimensionError("CtcHeading::contract: the tubes are not on one TDomain");
  }
  const std::size_t n = px_t.nb_slices();
  // An empty distance or turn rate anywhere: no trajectory.
  bool ok = !d_t.is_empty() && !w_t.is_empty();
  detail::HeadingTube px(px_t), py(py_t), psi(psi_t);
  const Interval tr = Interval(-1, 1) * Interval(track);
  const Interval pi = Interval::pi();
  std::vector<Interval> ix(n), iy(n), dir(n);
  for (int pass = 0; pass < 5 && ok; ++pass) {
    // The directions of travel, their cosines and sines by the batch rows, then the steps.
    for (std::size_t k = 0; k < n; ++k) dir[k] = psi.slices[k] + tr;
    detail::cos_rows(dir.data(), ix.data(), n);
    detail::sin_rows(dir.data(), iy.data(), n);
    for (std::size_t k = 0; k < n && ok; ++k) {
      const Interval dk = d_t.data().slices[k] & Interval::pos_reals();
      if (dk.is_empty()) ok = false;  // d was given empty: the network names its first empty atom
      ix[k] = dk * ix[k], iy[k] = dk * iy[k];
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
      const Interval r = detail::box_direction(dx, dy) + Interval(-1, 1) * (spread + Interval(track));
      const Interval before = psi.slices[k];
      const Interval kept = detail::periodic_meet(before, r);
      if (!detail::narrow(psi.slices[k], kept)) at = {2, 2 * k + 1}, ok = false;
      else if (!detail::narrow(psi.gates[k], kept)) at = {2, 2 * k}, ok = false;
      else if (!detail::narrow(psi.gates[k + 1], kept)) at = {2, 2 * k + 2}, ok = false;
      again = again || shrank(before, psi.slices[k], 0.01);
    }
    if (!again) break;
  }
  return detail::finish_heading(ok, px_t, py_t, psi_t);
}

// cn.add(ctc, {px, py, psi, d, w}): the five tubes, whole, on one TDomain.
class HeadingNode : public detail::HeadingNodeBase {
 public:
  HeadingNode(const CtcHeading& ctc, const std::vector<BoundDomain>& args)
      : HeadingNodeBase("CtcHeading", args, 5, "p (2 components), psi, d and w"), ctc_(ctc) {}
  bool run(NodeRun& r) const override {
    return run_heading(r, [&](detail::HeadingEmptyAt& at) {
      return contract_heading(tube_arg(0), tube_arg(1), tube_arg(2), tube_arg(3), tube_arg(4), ctc_.track(), at);
    });
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
  const bool ok = contract(p[0], p[1], psi, d, w);
  return ok;
}

std::shared_ptr<const CnNode> CtcHeading::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<HeadingNode>(*this, args);
}

}  // namespace sillage
