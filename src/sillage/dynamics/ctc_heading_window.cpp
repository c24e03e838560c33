#include "sillage/dynamics/ctc_heading_window.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <mutex>
#include <vector>

#include "sillage/dynamics/heading_common.h"
#include "sillage/dynamics/heading_window_inputs.h"
#include "sillage/error.h"
#include "sillage/interval/arith_rows.h"
#include "sillage/interval/trig_batch.h"

namespace sillage {

namespace {

// The cells of the heading tried against a window: at least kCell wide, at most kMaxCells.
constexpr double kCell = 0.01;
constexpr int kMaxCells = 128;

// The direction of a nonzero v in the box V whose parts each point into the
// arc `cone` (relative to ψ(t_c)): when the arc is narrower than π, every
// positive combination of them points into it too, whatever their lengths;
// then also the directions of the box V if it excludes 0. All the reals when
// neither says anything.
Interval travel_direction(const Interval& vx, const Interval& vy, const Interval& cone) {
  const bool box = !(vx.contains(0) && vy.contains(0));
  if (cone.is_empty() || !(cone.diam() < Interval::pi().lb())) {
    return box ? detail::box_direction(vx, vy) : Interval::all_reals();
  }
  return box ? detail::periodic_meet(cone, detail::box_direction(vx, vy)) : cone;
}

// rx = co vx − si vy and ry = si vx + co vy for rows of m cells (tmp: scratch), the bits of
// Interval's operators: with the AVX2 rows where they run, else one at a time.
void turn_rows(const Interval* co, const Interval* si, const Interval& vx, const Interval& vy, Interval* rx,
               Interval* ry, Interval* tmp, std::size_t m) {
  using detail::RowArg, detail::RowOp;
  if (!detail::avx2_rows_for(m)) {
    for (std::size_t i = 0; i < m; ++i) rx[i] = co[i] * vx - si[i] * vy, ry[i] = si[i] * vx + co[i] * vy;
    return;
  }
  detail::arith_rows_avx2(RowOp::Mul, rx, RowArg{co}, RowArg{&vx, true}, m);
  detail::arith_rows_avx2(RowOp::Mul, tmp, RowArg{si}, RowArg{&vy, true}, m);
  detail::arith_rows_avx2(RowOp::Sub, rx, RowArg{rx}, RowArg{tmp}, m);
  detail::arith_rows_avx2(RowOp::Mul, ry, RowArg{si}, RowArg{&vx, true}, m);
  detail::arith_rows_avx2(RowOp::Mul, tmp, RowArg{co}, RowArg{&vy, true}, m);
  detail::arith_rows_avx2(RowOp::Add, ry, RowArg{ry}, RowArg{tmp}, m);
}

// The window starting at slice a: the least b with t_b − t_a >= window
// (from b, the previous window's end); false if there is none (the last
// windows are shorter: skipped).
bool next_window(const TDomain& td, const CtcHeadingWindow& ctc, std::size_t a, std::size_t& b) {
  const auto t = td.times();
  const std::size_t n = t.size() - 1;
  b = std::max(b, a + 1);
  while (b <= n && t[b] - t[a] < ctc.window()) ++b;
  return b <= n;
}

// The first window's start: windows start at the slices numbered a multiple
// of the stride since the TDomain's first day, so that a domain that forgot
// its past (online) keeps the windows a batch solve of the whole mission has.
std::size_t first_window(const TDomain& td, const CtcHeadingWindow& ctc) {
  return (ctc.stride() - td.nb_forgotten() % ctc.stride()) % ctc.stride();
}

// Whether one of the sorted time atoms `dirty` lies in [lo, hi].
bool any_in(const std::vector<std::size_t>& dirty, std::size_t lo, std::size_t hi) {
  const auto it = std::lower_bound(dirty.begin(), dirty.end(), lo);
  return it != dirty.end() && *it <= hi;
}

// Whether a window holds a changed atom (`dirty`: sorted, as below).
bool any_dirty_window(const TDomain& td, const CtcHeadingWindow& ctc, const std::vector<std::size_t>& dirty) {
  if (dirty.empty()) return false;
  std::size_t b = 0;
  for (std::size_t a = first_window(td, ctc); a < td.nb_slices() && next_window(td, ctc, a, b); a += ctc.stride()) {
    if (any_in(dirty, 2 * a, 2 * b)) return true;
  }
  return false;
}

// `dirty` (null: every window): the time atoms that changed since the last
// run, sorted; a window [a, b] is contracted again only if one of its atoms
// 2a..2b changed. `in`: the inputs
// and sums of the windows, as left by the last contraction (a node's) or new.
bool contract_window(Tube& px_t, Tube& py_t, Tube& psi_t, const Tube& d_t, const Tube& dpsi_t, const Tube& w_t,
                     const CtcHeadingWindow& ctc, detail::HeadingEmptyAt& at, detail::WindowInputs& in,
                     const std::vector<std::size_t>* dirty = nullptr) {
  const auto td = px_t.tdomain();
  for (const Tube* t : std::initializer_list<const Tube*>{&py_t, &psi_t, &d_t, &dpsi_t, &w_t}) {
    if (t->tdomain() != td) throw DimensionError("CtcHeadingWindow::contract: the tubes are not on one TDomain");
  }
  const std::size_t n = px_t.nb_slices();
  // An empty input anywhere: no trajectory (checked before reading the slices).
  if (d_t.is_empty() || dpsi_t.is_empty() || w_t.is_empty() || px_t.is_empty() || py_t.is_empty() || psi_t.is_empty()) {
    return detail::finish_heading(false, px_t, py_t, psi_t);
  }
  detail::HeadingTube px(px_t), py(py_t), psi(psi_t);
  bool ok = in.update(*td, d_t.data(), dpsi_t.data(), w_t.data(), ctc.turn_accel(), ctc.track());
  std::size_t b = 0;
  for (std::size_t a = first_window(*td, ctc); a < n && ok; a += ctc.stride()) {
    if (!next_window(*td, ctc, a, b)) break;
    if (dirty && !any_in(*dirty, 2 * a, 2 * b)) continue;  // nothing changed in the window
    const std::size_t c = (a + b) / 2;
    const auto& [vx, vy, cone] = in.sum(a, b, c);
    // Heading: the directions of the displacement against those of V.
    const Interval dx = px.gates[b] - px.gates[a], dy = py.gates[b] - py.gates[a];
    const Interval dir_v = travel_direction(vx, vy, cone);
    if (!(dx.contains(0) && dy.contains(0)) && !dir_v.is_all_reals()) {
      // A displacement that is not 0: its direction is that of V turned by ψ(t_c).
      const Interval r = detail::box_direction(dx, dy) - dir_v;
      if (!detail::narrow(psi.gates[c], detail::periodic_meet(psi.gates[c], r))) {
        at = {2, 2 * c}, ok = false;
        break;
      }
    }
    // Both ways at once on cells of [ψ](t_c): the cells whose turn of V misses Δ are removed, and
    // the displacement lies in the hull of the turns of V by the cells kept.
    Interval& th = psi.gates[c];
    if (th.is_unbounded()) continue;
    Interval kept = Interval::empty(), hx = Interval::empty(), hy = Interval::empty();
    const int cells = static_cast<int>(std::clamp(std::ceil(th.diam() / kCell), 1.0, static_cast<double>(kMaxCells)));
    const auto m = static_cast<std::size_t>(cells);
    thread_local std::vector<Interval> cell(kMaxCells), co(kMaxCells), si(kMaxCells), rx(kMaxCells), ry(kMaxCells),
        tmp(kMaxCells);
    const double lo0 = th.lb(), width = th.diam();
    for (int i = 0; i < cells; ++i) {
      // The cells cover [th] exactly: the ends are th's, neighbours share their bound.
      const double lo = i == 0 ? lo0 : lo0 + width * i / cells;
      const double hi = i + 1 == cells ? th.ub() : lo0 + width * (i + 1) / cells;
      cell[i] = Interval(lo, hi);
    }
    detail::cos_rows(cell.data(), co.data(), m);
    detail::sin_rows(cell.data(), si.data(), m);
    // V turned by each cell: rx = co vx − si vy, ry = si vx + co vy (rows: the operators' bits).
    turn_rows(co.data(), si.data(), vx, vy, rx.data(), ry.data(), tmp.data(), m);
    for (std::size_t i = 0; i < m; ++i) {
      const Interval ex = rx[i] & dx, ey = ry[i] & dy;
      if (ex.is_empty() || ey.is_empty()) continue;
      kept |= cell[i], hx |= ex, hy |= ey;
    }
    if (!detail::narrow(th, kept)) at = {2, 2 * c}, ok = false;
    else if (!detail::narrow(px.gates[b], px.gates[a] + hx)) at = {0, 2 * b}, ok = false;
    else if (!detail::narrow(py.gates[b], py.gates[a] + hy)) at = {1, 2 * b}, ok = false;
    else if (!detail::narrow(px.gates[a], px.gates[b] - hx)) at = {0, 2 * a}, ok = false;
    else if (!detail::narrow(py.gates[a], py.gates[b] - hy)) at = {1, 2 * a}, ok = false;
  }
  return detail::finish_heading(ok, px_t, py_t, psi_t);
}

// cn.add(ctc, {px, py, psi, d, dpsi, w}): the six tubes, whole, on one TDomain.
class HeadingWindowNode : public detail::HeadingNodeBase {
 public:
  HeadingWindowNode(const CtcHeadingWindow& ctc, const std::vector<BoundDomain>& args)
      : HeadingNodeBase("CtcHeadingWindow", args, 6, "p (2 components), psi, d, dpsi and w"), ctc_(ctc) {}
  bool run(NodeRun& r) const override {
    // The time atoms changed (of any of the six tubes), sorted: the windows holding one run again.
    bool constants = false;
    const std::vector<std::size_t> dirty = dirty_time_atoms(r, constants);
    const bool every = r.all || constants;
    // No window holds what changed: nothing to do (most runs of an online update).
    if (!every && !any_dirty_window(*tube_arg(0).tdomain(), ctc_, dirty)) return true;
    const std::lock_guard<std::mutex> lock(*mutex_);
    return run_heading(r, [&](detail::HeadingEmptyAt& at) {
      return contract_window(tube_arg(0), tube_arg(1), tube_arg(2), tube_arg(3), tube_arg(4), tube_arg(5), ctc_, at,
                             *inputs_, every ? nullptr : &dirty);
    });
  }

 private:
  CtcHeadingWindow ctc_;
  // The inputs and window sums of the last run: a cache checked slice by slice (heading_window_inputs.h).
  std::shared_ptr<std::mutex> mutex_ = std::make_shared<std::mutex>();
  std::shared_ptr<detail::WindowInputs> inputs_ = std::make_shared<detail::WindowInputs>();
};

}  // namespace

CtcHeadingWindow::CtcHeadingWindow(double window, double track, double turn_accel, std::size_t stride)
    : window_(window), track_(track), turn_accel_(turn_accel), stride_(stride) {
  if (!(window > 0) || !std::isfinite(window)) {
    throw Error("CtcHeadingWindow: the window must be finite and > 0 s, got " + number_text(window));
  }
  if (!(track >= 0) || !std::isfinite(track)) {
    throw Error("CtcHeadingWindow: the track error must be finite and >= 0, got " + number_text(track));
  }
  if (!(turn_accel > 0)) {
    throw Error("CtcHeadingWindow: the turn acceleration must be > 0 (or inf), got " + number_text(turn_accel));
  }
  if (stride == 0) throw Error("CtcHeadingWindow: the stride must be >= 1 slice, got 0");
}

bool CtcHeadingWindow::contract(Tube& px, Tube& py, Tube& psi, const Tube& d, const Tube& dpsi, const Tube& w) const {
  detail::HeadingEmptyAt at;
  detail::WindowInputs in;
  return contract_window(px, py, psi, d, dpsi, w, *this, at, in);
}

bool CtcHeadingWindow::contract(TubeVector& p, Tube& psi, const Tube& d, const Tube& dpsi, const Tube& w) const {
  if (p.size() != 2) {
    throw DimensionError("CtcHeadingWindow::contract: p must have 2 components, got " + std::to_string(p.size()));
  }
  return contract(p[0], p[1], psi, d, dpsi, w);
}

std::shared_ptr<const CnNode> CtcHeadingWindow::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<HeadingWindowNode>(*this, args);
}

}  // namespace sillage
