// Tube::eval(t, v) and Tube::inverse(y, v): a tube read through its
// derivative tube. Inside slice k the trajectories of x with x' ∈ v lie in the
// polygon of CtcDeriv's slice rule (slice_deriv.h), computed here on a local
// copy of the slice (the tube itself is not changed).
#include <algorithm>
#include <span>
#include <string>
#include <type_traits>

#include "sillage/error.h"
#include "sillage/interval/rounding_policies.h"
#include "sillage/tube/envelope_pair.h"
#include "sillage/tube/eval_in_slice.h"
#include "sillage/tube/slice_deriv.h"
#include "sillage/tube/tube.h"

namespace sillage {

namespace {

// Slice k of x with its gates, contracted locally by the slice rule (gates
// into the slice, forward and backward): the polygon's inputs. R: the rounding
// policy (both give the same bits; CtcEval evaluates in its inner loop).
template <class R>
struct LocalSlice {
  double alo, ahi, blo, bhi, slo, shi, vlo, vhi;
  double t0, t1;
  detail::Width w;
  bool ok;  // false: something is empty, the tube holds no trajectory

  LocalSlice(const TubeData& x, const TubeData& v, std::span<const double> ts, std::size_t k)
      : alo(x.gates[k].lb()), ahi(x.gates[k].ub()), blo(x.gates[k + 1].lb()), bhi(x.gates[k + 1].ub()),
        slo(x.slices[k].lb()), shi(x.slices[k].ub()), vlo(v.slices[k].lb()), vhi(v.slices[k].ub()), t0(ts[k]),
        t1(ts[k + 1]), w(detail::width<R>(t0, t1)) {
    ok = detail::contract_slice<R, true, true, false>(alo, ahi, blo, bhi, slo, shi, vlo, vhi, w);
  }

  // Hull of the polygon ∩ [x](k) over t ∈ [c1, c2] ⊆ [t0, t1] (ok required).
  Interval hull(double c1, double c2) const {
    // R's differences: exact and without a branch on the data (rounding.h's branch on the error).
    const double tau_lo = R::sub_down(c1, t0), tau_hi = R::sub_up(c2, t0);
    const double sig_lo = R::sub_down(t1, c2), sig_hi = R::sub_up(t1, c1);
    double up, lo;
#if SILLAGE_PAIR_LANES
    if constexpr (std::is_same_v<R, detail::SoftRounding>) {  // both envelopes at once, the same bits
      using L = detail::PairLanes;
      const L::P e = detail::EnvelopePair::upper(L::make(ahi, -alo), L::make(bhi, -blo), L::make(vhi, -vlo),
                                                 L::make(vlo, -vhi), tau_lo, tau_hi, sig_lo, sig_hi, w.hi);
      up = L::lane0(e);
      lo = -L::lane1(e);
    } else
#endif
    {
      up = detail::upper_envelope<R>(ahi, bhi, vhi, vlo, tau_lo, tau_hi, sig_lo, sig_hi, w.hi);
      lo = -detail::upper_envelope<R>(-alo, -blo, -vlo, -vhi, tau_lo, tau_hi, sig_lo, sig_hi, w.hi);
    }
    const double h_lo = std::max(lo, slo), h_hi = std::min(up, shi);
    return h_lo <= h_hi ? Interval::from_bounds_unchecked(h_lo, h_hi) : Interval::empty();
  }
};

// Shrinks [lo, hi] ⊆ [t0, t1] to (an enclosure of) the times where
//   A + τP >= Y  and  B - σQ >= Y,   τ = t - t0, σ = t1 - t,
// i.e. where the upper bound of the polygon reaches Y. False if none.
// Thresholds are rounded so that no such time is cut.
bool cut_times(double A, double B, double P, double Q, double Y, double t0, double t1, double& lo, double& hi) {
  using namespace rounding;
  if (Y == -kInf) return true;
  if (!(A >= Y)) {  // A + τP >= Y needs τ >= (Y - A) / P
    if (P <= 0) return false;
    if (P < kInf) lo = std::max(lo, add_down(t0, div_down(sub_down(Y, A), P)));
  } else if (P < 0) {  // τ <= (A - Y) / -P
    hi = std::min(hi, add_up(t0, div_up(sub_up(A, Y), -P)));
  }
  const double R = -Q;  // B + σR >= Y
  if (!(B >= Y)) {      // σ >= (Y - B) / R
    if (R <= 0) return false;
    if (R < kInf) hi = std::min(hi, sub_up(t1, div_down(sub_down(Y, B), R)));
  } else if (R < 0) {  // σ <= (B - Y) / -R
    lo = std::max(lo, sub_down(t1, div_up(sub_up(B, Y), -R)));
  }
  return lo <= hi;
}

void check_v(const Tube& x, const Tube& v, const char* where) {
  if (x.tdomain() != v.tdomain()) {
    throw DimensionError(std::string(where) + ": x and v are not on the same TDomain (" +
                         std::to_string(x.nb_slices()) + " and " + std::to_string(v.nb_slices()) + " slices)");
  }
}

// Up to this many whole slices inside [t], their polygons are hulled one by
// one; beyond, the synthesis tree answers for them (their codomains, O(log N)).
constexpr std::size_t kPolygonScanLimit = 256;

}  // namespace

namespace {

// Slice k's polygon ∩ [x](k) over [c1, c2] ⊆ [t_k, t_{k+1}]; empty if the slice holds no trajectory.
template <class R>
Interval slice_part(const TubeData& x, const TubeData& v, std::span<const double> ts, std::size_t k, double c1,
                    double c2) {
  const LocalSlice<R> s(x, v, ts, k);
  return s.ok ? s.hull(c1, c2) : Interval::empty();
}

}  // namespace

Interval detail::eval_in_slice(const TubeData& x, const TubeData& v, std::span<const double> ts, std::size_t k,
                               double c1, double c2) {
  return detail::with_policy([&]<class R>() { return slice_part<R>(x, v, ts, k, c1, c2); });
}

Interval Tube::eval(const Interval& t, const Tube& v) const {
  const char* where = "Tube::eval(t, v)";
  check_v(*this, v, where);
  if (t.is_empty()) return Interval::empty();
  std::size_t first = 0, last = 0;
  slice_range(*td_, t, first, last, where);  // Error if t is not inside the domain
  return detail::with_policy([&]<class R>() -> Interval {
    const auto ts = td_->times();
    const TubeData& dx = *data_;
    const TubeData& dv = *v.data_;

    if (t.is_degenerate()) {
      const double c = t.lb();
      const std::ptrdiff_t g = td_->time_index(c);
      if (g < 0) return slice_part<R>(dx, dv, ts, first, c, c);
      // A time point: the gate, seen from both neighbouring slices.
      const auto k = static_cast<std::size_t>(g);
      double lo = dx.gates[k].lb(), hi = dx.gates[k].ub();
      if (k > 0) {
        const LocalSlice<R> s(dx, dv, ts, k - 1);
        if (!s.ok) return Interval::empty();
        lo = std::max(lo, s.blo);
        hi = std::min(hi, s.bhi);
      }
      if (k < nb_slices()) {
        const LocalSlice<R> s(dx, dv, ts, k);
        if (!s.ok) return Interval::empty();
        lo = std::max(lo, s.alo);
        hi = std::min(hi, s.ahi);
      }
      return lo <= hi ? Interval::from_bounds_unchecked(lo, hi) : Interval::empty();
    }

    // The two end slices over their part of [t], the slices between in full.
    Interval r = Interval::empty();
    auto add_slice = [&](std::size_t k) {
      const Interval h = slice_part<R>(dx, dv, ts, k, std::max(t.lb(), ts[k]), std::min(t.ub(), ts[k + 1]));
      if (h.is_empty()) return false;
      r |= h;
      return true;
    };
    if (!add_slice(first)) return Interval::empty();
    if (last == first) return r;
    if (!add_slice(last)) return Interval::empty();
    if (last - first - 1 > kPolygonScanLimit) {
      r |= (*this)(Interval(ts[first + 1], ts[last]));
    } else {
      for (std::size_t k = first + 1; k < last; ++k) {
        if (!add_slice(k)) return Interval::empty();
      }
    }
    return r;
  });
}

namespace {

// Hull of the times of slices first..last where the polygon meets y, within
// [ta, tb]; empty if none (or if a slice holds no trajectory).
template <class R>
Interval inverse_polygon(const TubeData& dx, const TubeData& dv, std::span<const double> ts, const Interval& y,
                         std::size_t first, std::size_t last, double ta, double tb) {
  double r_lo = rounding::kInf, r_hi = -rounding::kInf;
  for (std::size_t k = first; k <= last; ++k) {
    const LocalSlice<R> s(dx, dv, ts, k);
    if (!s.ok) return Interval::empty();  // no trajectory at all
    if (!(s.slo <= y.ub() && y.lb() <= s.shi)) continue;
    double lo = s.t0, hi = s.t1;
    // Upper bound of the polygon >= y⁻, and lower bound <= y⁺ (mirrored).
    if (!cut_times(s.ahi, s.bhi, s.vhi, s.vlo, y.lb(), s.t0, s.t1, lo, hi)) continue;
    if (!cut_times(-s.alo, -s.blo, -s.vlo, -s.vhi, -y.ub(), s.t0, s.t1, lo, hi)) continue;
    lo = std::max(lo, ta);
    hi = std::min(hi, tb);
    if (lo > hi) continue;
    r_lo = std::min(r_lo, lo);
    r_hi = std::max(r_hi, hi);
  }
  return r_lo <= r_hi ? Interval::from_bounds_unchecked(r_lo, r_hi) : Interval::empty();
}

}  // namespace

Interval Tube::inverse(const Interval& y, const Tube& v) const {
  check_v(*this, v, "Tube::inverse(y, v)");
  if (y.is_empty()) return Interval::empty();
  const auto ts = td_->times();
  return detail::with_policy([&]<class R>() {
    return inverse_polygon<R>(*data_, *v.data_, ts, y, 0, nb_slices() - 1, ts.front(), ts.back());
  });
}

Interval Tube::inverse(const Interval& y, const Tube& v, const Interval& t) const {
  const char* where = "Tube::inverse(y, v, t)";
  check_v(*this, v, where);
  if (y.is_empty() || t.is_empty()) return Interval::empty();
  std::size_t first = 0, last = 0;
  slice_range(*td_, t, first, last, where);  // Error if t is not inside the domain
  return detail::with_policy([&]<class R>() {
    return inverse_polygon<R>(*data_, *v.data_, td_->times(), y, first, last, t.lb(), t.ub());
  });
}

}  // namespace sillage
