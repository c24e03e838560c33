#include "sillage/tube/tube_builders.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sillage/error.h"
#include "sillage/interval/rounding.h"

namespace sillage {

namespace {

void check_error(double e, const char* where) {
  if (!(e >= 0) || !std::isfinite(e)) {
    std::ostringstream os;
    os << where << ": the error bound must be a finite number >= 0, got " << e;
    throw Error(os.str());
  }
}

void check_covers(const TDomain& td, const Trajectory& x, const char* where) {
  if (!td.t0_tf().is_subset(x.domain())) {
    throw Error(std::string(where) + ": the trajectory's domain " + x.domain().str() +
                " does not cover the TDomain " + td.t0_tf().str());
  }
}

// Enclosure of x over [t] (a sub-interval of the time axis, possibly
// degenerate) under the data + derivative assumptions.
class DerivativeBound {
 public:
  DerivativeBound(const Trajectory& data, double e, const Interval& dx)
      : ts_(data.sample_times()), ys_(data.sample_values()), e_(e), dx_(dx) {}

  Interval operator()(const Interval& t) const {
    Interval r = Interval::empty();
    const std::size_t m = ts_.size();
    if (t.lb() < ts_.front()) r |= backward(0, t & Interval(t.lb(), ts_.front()));
    if (t.ub() > ts_.back()) r |= forward(m - 1, t & Interval(ts_.back(), t.ub()));
    // pieces [t_i, t_{i+1}] that meet [t]
    auto i0 = static_cast<std::size_t>(std::upper_bound(ts_.begin(), ts_.end(), t.lb()) - ts_.begin());
    i0 = i0 == 0 ? 0 : std::min(i0 - 1, m >= 2 ? m - 2 : 0);  // t at the last sample: the last piece
    for (std::size_t i = i0; i + 1 < m && ts_[i] <= t.ub(); ++i) {
      const Interval piece = t & Interval(ts_[i], ts_[i + 1]);
      if (!piece.is_empty()) r |= between(i, piece);
    }
    if (m == 1 && t.contains(ts_[0])) r |= y(0);
    return r;
  }

 private:
  Interval y(std::size_t i) const { return Interval(ys_[i]) + Interval(-e_, e_); }
  Interval forward(std::size_t i, const Interval& t) const { return y(i) + (t - Interval(ts_[i])) * dx_; }
  Interval backward(std::size_t i, const Interval& t) const { return y(i) - (Interval(ts_[i]) - t) * dx_; }

  // Hull of forward(i, t) ∩ backward(i+1, t) over t in T ⊆ [t_i, t_{i+1}].
  // The upper bound min(two lines) is concave in t, the lower one convex:
  // splitting T where the two lines cross makes the interval evaluation on
  // each half tight. The split point needs no rigor: the halves cover T.
  Interval between(std::size_t i, const Interval& t) const {
    const double p = dx_.ub(), q = dx_.lb(), ti = ts_[i], tj = ts_[i + 1];
    const Interval yi = y(i), yj = y(i + 1);
    auto split = [&](double num, double den) {
      const double s = num / den;
      return std::isfinite(s) ? std::clamp(s, t.lb(), t.ub()) : t.lb();
    };
    const double su = split(yj.ub() - yi.ub() + p * ti - q * tj, p - q);
    const double sl = split(yj.lb() - yi.lb() + q * ti - p * tj, q - p);
    double hi = -rounding::kInf, lo = rounding::kInf;
    for (const Interval& h : {Interval(t.lb(), su), Interval(su, t.ub())}) {
      hi = std::max(hi, std::min(forward(i, h).ub(), backward(i + 1, h).ub()));
    }
    for (const Interval& h : {Interval(t.lb(), sl), Interval(sl, t.ub())}) {
      lo = std::min(lo, std::max(forward(i, h).lb(), backward(i + 1, h).lb()));
    }
    return lo <= hi ? Interval(lo, hi) : Interval::empty();
  }

  const std::vector<double>& ts_;
  const std::vector<double>& ys_;
  double e_;
  Interval dx_;
};

}  // namespace

Tube tube_from_data(std::shared_ptr<TDomain> td, const Trajectory& d, double error) {
  if (!td) throw Error("tube_from_data(td, d, error): null TDomain");
  check_error(error, "tube_from_data(td, d, error)");
  check_covers(*td, d, "tube_from_data(td, d, error)");
  const Interval e(-error, error);
  std::vector<Interval> slices(td->nb_slices()), gates(td->nb_slices() + 1);
  // An analytic d undefined somewhere: nothing known there (as Tube(td, f)).
  for (std::size_t k = 0; k < slices.size(); ++k) slices[k] = detail::unknown_where_undefined(d(td->slice_domain(k)) + e);
  for (std::size_t k = 0; k < gates.size(); ++k) gates[k] = detail::unknown_where_undefined(d(td->t(k)) + e);
  return Tube(std::move(td), slices, gates);
}

Tube tube_from_bounds(std::shared_ptr<TDomain> td, const Trajectory& lb, const Trajectory& ub) {
  if (!td) throw Error("tube_from_bounds(td, lb, ub): null TDomain");
  check_covers(*td, lb, "tube_from_bounds(td, lb, ub): lb");
  check_covers(*td, ub, "tube_from_bounds(td, lb, ub): ub");
  auto between = [](const Interval& l, const Interval& u) {
    return l.lb() <= u.ub() ? Interval(l.lb(), u.ub()) : Interval::empty();
  };
  std::vector<Interval> slices(td->nb_slices()), gates(td->nb_slices() + 1);
  for (std::size_t k = 0; k < slices.size(); ++k) {
    const Interval t = td->slice_domain(k);
    slices[k] = between(lb(t), ub(t));
  }
  for (std::size_t k = 0; k < gates.size(); ++k) gates[k] = between(lb(td->t(k)), ub(td->t(k)));
  return Tube(std::move(td), slices, gates);
}

Tube tube_from_data(std::shared_ptr<TDomain> td, const Trajectory& data, double error, const Interval& dx) {
  const char* where = "tube_from_data(td, data, error, dx)";
  if (!td) throw Error(std::string(where) + ": null TDomain");
  if (!data.is_sampled()) throw Error(std::string(where) + ": data must be a sampled trajectory");
  check_error(error, where);
  if (dx.is_empty()) throw Error(std::string(where) + ": the derivative bounds dx are empty");
  const DerivativeBound bound(data, error, dx);
  std::vector<Interval> slices(td->nb_slices()), gates(td->nb_slices() + 1);
  for (std::size_t k = 0; k < slices.size(); ++k) slices[k] = bound(td->slice_domain(k));
  for (std::size_t k = 0; k < gates.size(); ++k) gates[k] = bound(Interval(td->t(k)));
  return Tube(std::move(td), slices, gates);
}

}  // namespace sillage
