// CtcIvp: sweeps of validated integration over a tube (ctc_ivp.h).
#include "sillage/dynamics/ctc_ivp.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "sillage/dynamics/ivp_memory.h"
#include "sillage/dynamics/ivp_step.h"
#include "sillage/error.h"

namespace sillage {

using detail::IvpStepper;
using detail::LohnerSet;
using detail::TaylorOde;

namespace {

enum class Crossing { Done, Lost, Empty };

// The tube knows the set much better than the enclosure does in some
// direction: start again from the box rather than keep a loose wrapping.
bool much_tighter(const IntervalVector& before, const IntervalVector& after) {
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (after[i].diam() < 0.5 * before[i].diam()) return true;
  }
  return false;
}

// Intersects the set with a box known to hold the states; false if empty.
bool meet(detail::LohnerSet& set, const IntervalVector& known) {
  const IntervalVector b = set.box & known;
  if (b.is_empty()) return false;
  if (much_tighter(set.box, b)) {
    set = LohnerSet::from_box(b, set.zonotope);
  } else {
    set.box = b;
  }
  return true;
}

// From t_from to t_to (a slice) in steps that end exactly at t_to; `range`
// receives the hull of the enclosures over the steps. The token is checked
// at every step: a slice may take many.
Crossing cross_slice(const IvpStepper& stepper, LohnerSet& set, double t_from, double t_to, const IntervalVector& u,
                     const IntervalVector& slice, double sign, double tol, IntervalVector& range,
                     const CancelToken& cancel) {
  double tau = t_from;
  double hs = stepper.suggest(set, u, sign, tol);
  int guard = 0;
  while (tau != t_to) {
    check_cancel(cancel, "CtcIvp::contract");
    if (!(hs > 0.0) || ++guard > 100000) return Crossing::Lost;
    const double rem = std::abs(t_to - tau);
    const double next = hs >= 0.95 * rem ? t_to : tau + sign * hs;
    const Interval h = sign > 0 ? Interval(next) - Interval(tau) : Interval(tau) - Interval(next);
    IntervalVector r;
    if (!stepper.step(set, h, u, sign, r)) {
      hs = 0.5 * std::min(hs, rem);
      if (hs < 1e-12 * rem) return Crossing::Lost;
      continue;
    }
    range = range.is_empty() ? r : hull(range, r);
    tau = next;
    if (!meet(set, tau == t_to ? set.box : slice)) return Crossing::Empty;
    hs = stepper.suggest(set, u, sign, tol);
  }
  return Crossing::Done;
}

void set_empty(TubeVector& x) {
  for (std::size_t i = 0; i < x.size(); ++i) x[i].set(Interval::empty());
}

// Intersects gates and slices of x with enclosures, remembering which
// components changed; marks them modified when it goes, a cancelled sweep too.
class VectorWriter {
 public:
  explicit VectorWriter(TubeVector& x) : changed_(x.size(), false) {
    w_.reserve(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) w_.push_back(x[i].write());
  }
  ~VectorWriter() {
    for (std::size_t i = 0; i < w_.size(); ++i) w_[i].commit(changed_[i]);
  }
  VectorWriter(const VectorWriter&) = delete;
  VectorWriter& operator=(const VectorWriter&) = delete;
  void write(bool gate, std::size_t k, const IntervalVector& v) {
    for (std::size_t i = 0; i < w_.size(); ++i) {
      Interval& cur = gate ? w_[i].gates()[k] : w_[i].slices()[k];
      const Interval nv = cur & v[i];
      if (nv != cur) {
        cur = nv;
        changed_[i] = true;
      }
    }
  }
 private:
  std::vector<Tube::Writer> w_;
  std::vector<bool> changed_;
};

// A piece of a wide set (CtcIvp::set_max_pieces): the box it starts from,
// at sweep index j0, and the number of pieces it may still be cut into.
struct Piece {
  IntervalVector origin;
  std::size_t j0 = 0;
  std::size_t budget = 1;
};

// A piece whose box has grown this many times since its start is cut.
constexpr double kSplitGrowth = 2.0;

// Pushes the two halves of p's origin (its widest component; they cover
// it), each with half the budget.
void split(const Piece& p, std::vector<Piece>& stack) {
  const auto [l, r] = p.origin.bisect();
  stack.push_back(Piece{r, p.j0, p.budget - p.budget / 2});
  stack.push_back(Piece{l, p.j0, p.budget / 2});
}

}  // namespace

CtcIvp::CtcIvp(const Function& f, std::size_t nb_inputs, int order, TimePropag propag)
    : ode_(std::make_shared<detail::TaylorOde>(f)), order_(order), propag_(propag) {
  if (ode_->nb_inputs() != nb_inputs) {
    throw DimensionError("CtcIvp: f has " + std::to_string(f.nb_vars()) + " variables and " +
                         std::to_string(f.image_dim()) + " outputs, so " + std::to_string(ode_->nb_inputs()) +
                         " inputs, but nb_inputs = " + std::to_string(nb_inputs));
  }
  if (order < 1 || order > 60) throw Error("CtcIvp: the order must be in [1, 60], got " + std::to_string(order));
}

void CtcIvp::set_tolerance(double tol) {
  if (!(tol > 0.0) || !std::isfinite(tol)) throw Error("CtcIvp::set_tolerance: expected a positive tolerance");
  tol_ = tol;
}

bool CtcIvp::sweep(TubeVector& x, const TubeVector* u, double sign, detail::IvpMemory* memory,
                   const CancelToken& cancel) const {
  const std::size_t n = x.size(), N = x.nb_slices();
  const TDomain& td = *x.tdomain();
  const IvpStepper stepper(*ode_, order_);
  VectorWriter writer(x);
  auto write = [&](bool gate, std::size_t k, const IntervalVector& v) { writer.write(gate, k, v); };
  detail::LohnerSet set;
  bool active = false;
  // With a memory: resume at the first step whose tubes changed.
  std::size_t first = 0;
  std::vector<std::optional<LohnerSet>>* arriving = nullptr;
  if (memory) {
    first = memory->first_change(x, u, sign);
    arriving = &memory->arriving[sign > 0 ? 0 : 1];
    if (first > N) return true;  // nothing changed since the last run
    if (first > 0 && (*arriving)[first]) {
      set = *(*arriving)[first];
      active = true;
    }
    arriving->resize(N + 1);
  }
  for (std::size_t j = first; j <= N; ++j) {
    const std::size_t k = sign > 0 ? j : N - j;
    if (arriving) (*arriving)[j] = active ? std::optional<LohnerSet>(set) : std::nullopt;
    const IntervalVector g = x.gate(k);
    if (g.is_empty()) return false;
    if (active) {
      if (!meet(set, g)) return false;
      write(true, k, set.box);
    } else if (!g.is_unbounded()) {
      set = LohnerSet::from_box(g, u != nullptr && nb_inputs() > 0);
      active = true;
    }
    if (j == N || !active) continue;
    const std::size_t s = sign > 0 ? k : k - 1;
    const IntervalVector us = u ? u->slice(s) : IntervalVector(0);
    const IntervalVector slice = x.slice(s);
    IntervalVector range = IntervalVector::empty(n);
    const double to = sign > 0 ? td.t(k + 1) : td.t(k - 1);
    switch (cross_slice(stepper, set, td.t(k), to, us, slice, sign, tol_, range, cancel)) {
      case Crossing::Lost: active = false; break;
      case Crossing::Empty: return false;
      case Crossing::Done:
        write(false, s, range);
        if (x.slice(s).is_empty()) return false;
        break;
    }
  }
  return true;
}

void CtcIvp::set_max_pieces(std::size_t m) {
  if (m < 1) throw Error("CtcIvp::set_max_pieces: expected at least 1 piece, got 0");
  max_pieces_ = m;
}

bool CtcIvp::sweep_pieces(TubeVector& x, const TubeVector* u, double sign, const CancelToken& cancel) const {
  const std::size_t n = x.size(), N = x.nb_slices();
  const TDomain& td = *x.tdomain();
  const IvpStepper stepper(*ode_, order_);
  const bool zonotope = u != nullptr && nb_inputs() > 0;
  const auto gate_index = [&](std::size_t j) { return sign > 0 ? j : N - j; };
  for (std::size_t k = 0; k <= N; ++k) {
    if (x.gate(k).is_empty()) return false;
  }
  std::size_t start = 0;
  while (start <= N && x.gate(gate_index(start)).is_unbounded()) ++start;
  if (start > N) return true;
  // Each piece runs alone from its origin; its boxes join the hulls only
  // when it ends (a piece cut in two is replaced by its halves, from its
  // origin). Past `limit` (a piece that could not be validated nor cut)
  // nothing is known.
  std::vector<IntervalVector> gates(N + 1, IntervalVector::empty(n)), slices(N, IntervalVector::empty(n));
  std::size_t limit = N;  // last gate index (sweep order) where the hulls hold
  std::vector<Piece> stack{Piece{x.gate(gate_index(start)), start, max_pieces_}};
  while (!stack.empty()) {
    const Piece p = stack.back();
    stack.pop_back();
    LohnerSet set = LohnerSet::from_box(p.origin, zonotope);
    const double width0 = p.origin.max_diam();
    std::vector<IntervalVector> pg, ps;  // this piece's gate and slice boxes from j0
    bool cut = false;
    for (std::size_t j = p.j0; j <= limit; ++j) {
      const std::size_t k = gate_index(j);
      if (!meet(set, x.gate(k))) break;  // no solution of this piece passes here
      if (j > p.j0 && p.budget >= 2 && width0 > 0.0 && set.box.max_diam() > kSplitGrowth * width0) {
        split(p, stack);
        cut = true;
        break;
      }
      pg.push_back(set.box);
      if (j == N || j == limit) break;
      const std::size_t s = sign > 0 ? k : k - 1;
      const IntervalVector us = u ? u->slice(s) : IntervalVector(0);
      const double to = sign > 0 ? td.t(k + 1) : td.t(k - 1);
      IntervalVector r = IntervalVector::empty(n);
      const Crossing c = cross_slice(stepper, set, td.t(k), to, us, x.slice(s), sign, tol_, r, cancel);
      if (c == Crossing::Empty) break;
      if (c == Crossing::Lost) {
        if (p.budget >= 2 && width0 > 0.0) {
          split(p, stack);
          cut = true;
        } else {
          limit = std::min(limit, j);  // the gate j holds, the slice after it is unknown
        }
        break;
      }
      ps.push_back(r);
    }
    if (cut) continue;
    for (std::size_t i = 0; i < pg.size(); ++i) {
      IntervalVector& h = gates[p.j0 + i];
      h = h.is_empty() ? pg[i] : hull(h, pg[i]);
    }
    for (std::size_t i = 0; i < ps.size(); ++i) {
      IntervalVector& h = slices[p.j0 + i];
      h = h.is_empty() ? ps[i] : hull(h, ps[i]);
    }
  }
  // Gates start..limit and the slices between them: every solution lies in
  // the hull of the pieces (empty: none passes, the tube is empty).
  VectorWriter writer(x);
  for (std::size_t j = start; j <= limit; ++j) {
    const std::size_t k = gate_index(j);
    writer.write(true, k, gates[j]);
    if (x.gate(k).is_empty()) return false;
    if (j == limit) break;
    const std::size_t s = sign > 0 ? k : k - 1;
    writer.write(false, s, slices[j]);
    if (x.slice(s).is_empty()) return false;
  }
  return true;
}

void CtcIvp::check(const TubeVector& x, const TubeVector* u) const {
  if (!u && nb_inputs() != 0) {
    throw DimensionError("CtcIvp::contract: f has " + std::to_string(nb_inputs()) +
                         " inputs; give their tubes, contract(x, u)");
  }
  if (x.size() != nb_states()) {
    throw DimensionError("CtcIvp::contract: x has " + std::to_string(x.size()) + " components, f has " +
                         std::to_string(nb_states()) + " states");
  }
  if (!u) return;
  if (u->size() != nb_inputs()) {
    throw DimensionError("CtcIvp::contract: u has " + std::to_string(u->size()) + " components, f has " +
                         std::to_string(nb_inputs()) + " inputs");
  }
  if (u->tdomain() != x.tdomain()) throw DimensionError("CtcIvp::contract: x and u are not on the same TDomain");
}

bool CtcIvp::contract(TubeVector& x, const TubeVector& u, const CancelToken& cancel) const {
  check(x, &u);
  return contract_impl(x, &u, nullptr, cancel);
}

bool CtcIvp::contract(TubeVector& x, const CancelToken& cancel) const {
  check(x, nullptr);
  return contract_impl(x, nullptr, nullptr, cancel);
}

bool CtcIvp::contract(Tube& x, const CancelToken& cancel) const {
  TubeVector xv(std::vector<Tube>{x});
  const bool ok = contract(xv, cancel);
  x &= xv[0];
  return ok && !x.is_empty();
}

bool CtcIvp::contract(Tube& x, const Tube& u, const CancelToken& cancel) const {
  TubeVector xv(std::vector<Tube>{x});
  const TubeVector uv(std::vector<Tube>{u});
  const bool ok = contract(xv, uv, cancel);
  x &= xv[0];
  return ok && !x.is_empty();
}

bool CtcIvp::contract_impl(TubeVector& x, const TubeVector* u, detail::IvpMemory* memory,
                           const CancelToken& cancel) const {
  bool ok = true;
  // With pieces the memory (one set per gate) does not apply: a full run.
  const auto run = [&](double sign) {
    return max_pieces_ > 1 ? sweep_pieces(x, u, sign, cancel) : sweep(x, u, sign, memory, cancel);
  };
  try {
    if (has(propag_, TimePropag::FORWARD)) ok = run(1.0);
    if (ok && has(propag_, TimePropag::BACKWARD)) ok = run(-1.0);
  } catch (...) {  // Cancelled: a sweep cut short left sets in memory that x does not match
    if (memory) memory->forget();
    throw;
  }
  if (!ok) set_empty(x);
  if (memory) {
    if (ok) {
      memory->remember(x, u);
    } else {
      memory->forget();
    }
  }
  return ok;
}

bool CtcIvp::contract(TubeVector& x, const TubeVector* u, detail::IvpMemory& memory,
                      const CancelToken& cancel) const {
  check(x, u);
  return contract_impl(x, u, &memory, cancel);
}

std::size_t CtcIvp::nb_states() const { return ode_->nb_states(); }
std::size_t CtcIvp::nb_inputs() const { return ode_->nb_inputs(); }
const Function& CtcIvp::function() const { return ode_->function(); }

}  // namespace sillage
