#include "sillage/tube/trajectory.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sillage/error.h"

namespace sillage {

namespace {

void check_finite(double t, double x, const char* where) {
  if (!std::isfinite(t) || !std::isfinite(x)) {
    throw Error(std::string(where) + ": sample (" + number_text(t) + ", " + number_text(x) + ") is not finite");
  }
}

}  // namespace

Trajectory::Trajectory(const std::map<double, double>& samples) {
  if (samples.empty()) throw Error("Trajectory(samples): no sample");
  for (const auto& [t, x] : samples) {
    check_finite(t, x, "Trajectory(samples)");
    ts_.push_back(t);
    xs_.push_back(x);
  }
  domain_ = Interval(ts_.front(), ts_.back());
}

Trajectory::Trajectory(const std::vector<double>& times, const std::vector<double>& values) {
  if (times.size() != values.size()) {
    throw DimensionError("Trajectory(times, values): " + std::to_string(times.size()) + " times but " +
                         std::to_string(values.size()) + " values");
  }
  if (times.empty()) throw Error("Trajectory(times, values): no sample");
  for (std::size_t i = 0; i < times.size(); ++i) {
    check_finite(times[i], values[i], "Trajectory(times, values)");
    if (i > 0 && !(times[i - 1] < times[i])) {
      throw Error("Trajectory(times, values): times must be strictly increasing, but t[" + std::to_string(i - 1) +
                  "] = " + number_text(times[i - 1]) + " >= t[" + std::to_string(i) + "] = " + number_text(times[i]));
    }
  }
  ts_ = times;
  xs_ = values;
  domain_ = Interval(ts_.front(), ts_.back());
}

Trajectory::Trajectory(const Function& f, const Interval& domain)
    : f_(std::make_shared<Function>(f)), domain_(domain) {
  if (f.nb_vars() != 1 || f.image_dim() != 1) {
    throw DimensionError("Trajectory(f, domain): f must be a scalar function of one variable t");
  }
  if (domain.is_empty() || domain.is_unbounded()) {
    throw Error("Trajectory(f, domain): the domain must be bounded and non-empty, got " + domain.str());
  }
}

Trajectory::Trajectory(const std::string& expr_of_t, const Interval& domain)
    : Trajectory(Function({"t"}, expr_of_t), domain) {}

Trajectory::Trajectory(Eval eval, const Interval& domain) : eval_(std::move(eval)), domain_(domain) {
  if (!eval_) throw Error("Trajectory(eval, domain): no evaluation function");
  if (domain.is_empty() || domain.is_unbounded()) {
    throw Error("Trajectory(eval, domain): the domain must be bounded and non-empty, got " + domain.str());
  }
}

void Trajectory::check_time(double t, const char* where) const {
  if (!domain_.contains(t)) {
    throw Error(std::string(where) + ": t = " + number_text(t) + " is outside the trajectory's domain " + domain_.str());
  }
}

Interval Trajectory::interpolate(std::size_t i, const Interval& t) const {
  // x_i + (t - t_i) * (x_{i+1} - x_i) / (t_{i+1} - t_i): t occurs once, so the
  // interval evaluation is the exact range up to outward rounding.
  const Interval slope = (Interval(xs_[i + 1]) - Interval(xs_[i])) / (Interval(ts_[i + 1]) - Interval(ts_[i]));
  return Interval(xs_[i]) + (t - Interval(ts_[i])) * slope;
}

Interval Trajectory::operator()(double t) const {
  check_time(t, "Trajectory::operator()(t)");
  if (f_) return f_->eval(IntervalVector{Interval(t)});
  if (eval_) return eval_(Interval(t));
  const auto it = std::lower_bound(ts_.begin(), ts_.end(), t);
  const auto i = static_cast<std::size_t>(it - ts_.begin());
  if (*it == t) return Interval(xs_[i]);  // a sample: exact
  return interpolate(i - 1, Interval(t));
}

Interval Trajectory::operator()(const Interval& t) const {
  if (t.is_empty()) return Interval::empty();
  if (!t.is_subset(domain_)) {
    throw Error("Trajectory::operator()([t]): [t] = " + t.str() + " is not inside the trajectory's domain " +
                domain_.str());
  }
  if (f_) return f_->eval(IntervalVector{t});
  if (eval_) return eval_(t);
  // Piecewise linear: the range is the hull of the values at the ends of [t]
  // and of the samples strictly inside.
  Interval r = (*this)(t.lb()) | (*this)(t.ub());
  auto it = std::upper_bound(ts_.begin(), ts_.end(), t.lb());
  for (; it != ts_.end() && *it < t.ub(); ++it) r |= Interval(xs_[static_cast<std::size_t>(it - ts_.begin())]);
  return r;
}

void Trajectory::set(double t, double x) {
  if (!is_sampled()) throw Error("Trajectory::set(t, x): only a sampled trajectory takes samples");
  check_finite(t, x, "Trajectory::set(t, x)");
  const auto it = std::lower_bound(ts_.begin(), ts_.end(), t);
  const auto i = it - ts_.begin();
  if (it != ts_.end() && *it == t) {
    xs_[static_cast<std::size_t>(i)] = x;
  } else {
    ts_.insert(it, t);
    xs_.insert(xs_.begin() + i, x);
  }
  domain_ = Interval(ts_.front(), ts_.back());
}

}  // namespace sillage
