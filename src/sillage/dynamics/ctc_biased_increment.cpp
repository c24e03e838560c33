#include "sillage/dynamics/ctc_biased_increment.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "sillage/ctc/shrink.h"
#include "sillage/error.h"
#include "sillage/interval/rounding.h"

namespace sillage {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
// Rounds of (bias, sweep) per call: each only shrinks, the second usually changes nothing.
constexpr int kMaxRounds = 16;

// The upper convex hull of points added left to right (x increasing), and the
// vertex from which the slope to a point on the right of all of them is least:
// the line through it leaves every point below, so no earlier point gives a
// smaller slope. Plain doubles: it only picks a pair, whose bound is then
// computed with outward rounding, so an imperfect pick costs tightness, never
// soundness.
class UpperHull {
 public:
  void add(double x, double y, std::size_t id) {
    while (v_.size() >= 2 && cross(v_[v_.size() - 2], v_.back(), x, y) >= 0) v_.pop_back();
    v_.push_back({x, y, id});
  }
  // The id of the vertex of least slope to (x, y), kNone without vertices.
  std::size_t tangent(double x, double y) const {
    if (v_.empty()) return kNone;
    std::size_t lo = 0, hi = v_.size() - 1;
    while (lo < hi) {  // the slope falls, then rises, along the hull
      const std::size_t mid = (lo + hi) / 2;
      if (slope(v_[mid], x, y) <= slope(v_[mid + 1], x, y)) hi = mid;
      else lo = mid + 1;
    }
    return v_[lo].id;
  }

 private:
  struct Vertex {
    double x, y;
    std::size_t id;
  };
  static double cross(const Vertex& o, const Vertex& a, double x, double y) {
    return (a.x - o.x) * (y - o.y) - (a.y - o.y) * (x - o.x);
  }
  static double slope(const Vertex& a, double x, double y) { return (y - a.y) / (x - a.x); }
  std::vector<Vertex> v_;
};

// The exact sums of the lower and of the upper bounds of the increments from the first slice
// (enclosed): over a span i..j the increments sum to within [lo_j − lo_i, hi_j − hi_i], which
// the difference of interval prefix sums would widen by the width of every earlier slice.
struct Prefix {
  std::vector<Interval> lo, hi;
  explicit Prefix(const std::vector<Interval>& inc) : lo(inc.size() + 1, Interval(0.0)), hi(inc.size() + 1, Interval(0.0)) {
    for (std::size_t k = 0; k < inc.size(); ++k) {
      lo[k + 1] = lo[k] + (std::isfinite(inc[k].lb()) ? Interval(inc[k].lb()) : Interval::all_reals());
      hi[k + 1] = hi[k] + (std::isfinite(inc[k].ub()) ? Interval(inc[k].ub()) : Interval::all_reals());
    }
  }
};

// [b0] from every pair of gates i < j: b0 (t_j − t_i) ∈ S_ij − ([x](t_j) − [x](t_i)), S_ij the sum of
// the increments (widened by the drift) over i..j. For each j only the pairs picked by the hulls
// (least upper bound, greatest lower bound) are evaluated. Each bound is the one end of the
// interval expression that it needs, with the same directed roundings as the Interval
// operations (the same bits), t_j − t_i > 0 enclosed in [tl, tu].
Interval bias_from_spans(const TDomain& td, std::span<const Interval> gates, const Prefix& sum) {
  using namespace rounding;
  double blo = -kInf, bhi = kInf;
  UpperHull up, down;  // up: upper bounds of b0; down: lower bounds, on negated points
  const auto ts = td.times();
  const auto upper = [&](std::size_t i, std::size_t j) {  // b0 τ <= S_ij.ub − (l_j − u_i)
    if (i == kNone) return;
    const double n = sub_up(sub_up(sum.hi[j].ub(), sum.hi[i].lb()), sub_down(gates[j].lb(), gates[i].ub()));
    bhi = std::min(bhi, div_up(n, n >= 0 ? sub_down(ts[j], ts[i]) : sub_up(ts[j], ts[i])));
  };
  const auto lower = [&](std::size_t i, std::size_t j) {  // b0 τ >= S_ij.lb − (u_j − l_i)
    if (i == kNone) return;
    const double n = sub_down(sub_down(sum.lo[j].lb(), sum.lo[i].ub()), sub_up(gates[j].ub(), gates[i].lb()));
    blo = std::max(blo, div_down(n, n >= 0 ? sub_up(ts[j], ts[i]) : sub_down(ts[j], ts[i])));
  };
  for (std::size_t j = 0; j < gates.size(); ++j) {
    const double t = ts[j], ph = sum.hi[j].mid(), pl = sum.lo[j].mid(), l = gates[j].lb(), u = gates[j].ub();
    const bool fh = std::isfinite(ph), fl = std::isfinite(pl);
    if (fh && std::isfinite(l)) upper(up.tangent(t, ph - l), j);
    if (fl && std::isfinite(u)) lower(down.tangent(t, u - pl), j);
    if (!(blo <= bhi)) return Interval::empty();
    if (fh && std::isfinite(u)) up.add(t, ph - u, j);
    if (fl && std::isfinite(l)) down.add(t, l - pl, j);
  }
  return Interval(blo, bhi);
}

// x(t_{k+1}) − x(t_k) ∈ step_k = inc_k − [b0] δ_k, forward then backward (CtcIncrement's rule).
// False: empty.
bool sweep(std::span<Interval> g, const std::vector<Interval>& step) {
  const std::size_t n = step.size();
  for (std::size_t k = 0; k < n; ++k) {
    g[k + 1] &= g[k] + step[k];
    if (g[k + 1].is_empty()) return false;
  }
  for (std::size_t k = n; k-- > 0;) {
    g[k] &= g[k + 1] - step[k];
    if (g[k].is_empty()) return false;
  }
  return true;
}

// The slices of j ∩= [i](k) − [b0] δ_k + [−d, d] δ_k. False: empty (j set empty).
bool narrow_increments(Tube& j, const Tube& i, const Interval& b, double drift) {
  if (j.tdomain() != i.tdomain()) {
    throw DimensionError("CtcBiasedIncrement::contract(x, b0, i, j): i and j are not on one TDomain");
  }
  const TDomain& td = *i.tdomain();
  Tube::Writer w = j.write();
  const std::span<Interval> js = w.slices();
  const auto& is = i.data().slices;
  bool changed = false;
  for (std::size_t k = 0; k < js.size(); ++k) {
    const Interval now = js[k] & (is[k] + (Interval(-drift, drift) - b) * td.slice_width(k));
    changed = changed || now != js[k];
    js[k] = now;
    if (now.is_empty()) {
      w.commit();
      j.set(Interval::empty());
      return false;
    }
  }
  w.commit(changed);
  return true;
}

bool fail(Tube& x, Interval& b) {
  x.set(Interval::empty());
  b = Interval::empty();
  return false;
}

}  // namespace

CtcBiasedIncrement::CtcBiasedIncrement(double drift) : drift_(drift) {
  if (!(drift >= 0) || !std::isfinite(drift)) {
    throw Error("CtcBiasedIncrement: the in-run drift must be finite and >= 0, got " + number_text(drift));
  }
}

bool CtcBiasedIncrement::contract(Tube& x, Interval& b0, const Tube& i) const {
  if (x.tdomain() != i.tdomain()) {
    throw DimensionError("CtcBiasedIncrement::contract(x, b0, i): x and i are not on one TDomain");
  }
  // The increments are the slices of i (its gates are not read).
  const auto& slices = i.data().slices;
  const bool no_increment = std::any_of(slices.begin(), slices.end(), [](const Interval& s) { return s.is_empty(); });
  if (x.is_empty() || no_increment || b0.is_empty()) return fail(x, b0);
  const TDomain& td = *x.tdomain();
  const std::size_t n = x.nb_slices();
  std::vector<Interval> width(n), inc(n), step(n);
  for (std::size_t k = 0; k < n; ++k) {
    width[k] = td.slice_width(k);
    inc[k] = slices[k] + Interval(-drift_, drift_) * width[k];
  }
  const Prefix prefix(inc);
  Tube::Writer w = x.write();
  const std::span<Interval> gates = w.gates();
  const std::vector<Interval> before(gates.begin(), gates.end());
  for (int round = 0; round < kMaxRounds; ++round) {
    const Interval b = b0 & bias_from_spans(td, gates, prefix);
    if (b.is_empty()) return fail(x, b0);
    const bool moved = b != b0;
    b0 = b;
    if (round > 0 && !moved) break;  // the gates are already swept with this bias
    for (std::size_t k = 0; k < n; ++k) step[k] = inc[k] - b0 * width[k];
    if (!sweep(gates, step)) return fail(x, b0);
  }
  w.commit(!std::equal(gates.begin(), gates.end(), before.begin()));
  return true;
}

bool CtcBiasedIncrement::contract(Tube& x, Interval& b0, const Tube& i, Tube& j) const {
  if (j.tdomain() != x.tdomain()) {
    throw DimensionError("CtcBiasedIncrement::contract(x, b0, i, j): x and j are not on one TDomain");
  }
  if (contract(x, b0, i) && narrow_increments(j, i, b0, drift_)) return true;
  x.set(Interval::empty());
  j.set(Interval::empty());
  b0 = Interval::empty();
  return false;
}

}  // namespace sillage
