#include "sillage/tube/tdomain.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "sillage/error.h"
#include "sillage/tube/time_search.h"

namespace sillage {

namespace {

constexpr double kMaxSlices = 2147483648.0;  // 2^31

}  // namespace

void TubeData::split(std::size_t k) {
  const Interval y = slices[k];
  slices.insert(slices.begin() + static_cast<std::ptrdiff_t>(k) + 1, y);
  gates.insert(gates.begin() + static_cast<std::ptrdiff_t>(k) + 1, y);
  touch();
}

void TubeData::append() {
  slices.push_back(Interval());
  gates.push_back(Interval());
  touch();
}

void TubeData::drop_front(std::size_t m) {
  slices.erase(slices.begin(), slices.begin() + static_cast<std::ptrdiff_t>(m));
  gates.erase(gates.begin(), gates.begin() + static_cast<std::ptrdiff_t>(m));
  touch();
}

TDomain::TDomain(double t0, double tf, double dt) {
  if (!std::isfinite(t0) || !std::isfinite(tf)) {
    throw Error("TDomain(t0, tf, dt): t0 and tf must be finite, got t0 = " + number_text(t0) + ", tf = " + number_text(tf));
  }
  if (!(tf > t0)) {
    throw Error("TDomain(t0, tf, dt): need t0 < tf, got t0 = " + number_text(t0) + ", tf = " + number_text(tf));
  }
  if (!(dt > 0) || !std::isfinite(dt)) {
    throw Error("TDomain(t0, tf, dt): dt must be a finite positive number, got dt = " + number_text(dt));
  }
  const double estimate = std::ceil((tf - t0) / dt);
  if (!(estimate < kMaxSlices)) {
    throw Error("TDomain(t0, tf, dt): too many slices (" + number_text(estimate) + ") for dt = " + number_text(dt));
  }
  // n = number of points t0 + k*dt strictly below tf; the estimate is off by
  // at most one either way because of rounding.
  auto point = [&](std::size_t k) { return t0 + static_cast<double>(k) * dt; };
  std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(estimate));
  while (n > 1 && point(n - 1) >= tf) --n;
  while (point(n) < tf) ++n;
  // A last slice shorter than a rounding artefact is merged into the previous
  // one (e.g. t0 + 10*dt = tf - 1 ulp), so a uniform grid stays uniform.
  if (n > 1 && tf - point(n - 1) <= 1e-9 * dt) --n;
  times_.reserve(n + 1);
  for (std::size_t k = 0; k < n; ++k) times_.push_back(point(k));  // direct, never accumulated
  times_.push_back(tf);
  for (std::size_t k = 1; k < times_.size(); ++k) {
    if (!(times_[k - 1] < times_[k])) {
      throw Error("TDomain(t0, tf, dt): dt = " + number_text(dt) + " is below the resolution of doubles near t = " +
                  number_text(times_[k]));
    }
  }
}

TDomain::TDomain(std::vector<double> times) : times_(std::move(times)) {
  if (times_.size() < 2) {
    throw Error("TDomain(times): need at least two time points, got " + std::to_string(times_.size()));
  }
  for (std::size_t k = 0; k < times_.size(); ++k) {
    if (!std::isfinite(times_[k])) {
      throw Error("TDomain(times): time point " + std::to_string(k) + " is not finite (" + number_text(times_[k]) + ")");
    }
    if (k > 0 && !(times_[k - 1] < times_[k])) {
      throw Error("TDomain(times): time points must be strictly increasing, but t[" + std::to_string(k - 1) +
                  "] = " + number_text(times_[k - 1]) + " >= t[" + std::to_string(k) + "] = " + number_text(times_[k]));
    }
  }
  times_.shrink_to_fit();
}

double TDomain::t(std::size_t k) const {
  if (k >= times_.size()) {
    throw OutOfRangeError("TDomain::t(k): index " + std::to_string(k) + " out of range [0, " +
                std::to_string(nb_slices()) + "]");
  }
  return times_[k];
}

std::size_t TDomain::slice_index(double t) const {
  if (std::isnan(t)) throw Error("TDomain::slice_index(t): t is NaN");
  if (!(t >= times_.front() && t <= times_.back())) {
    throw Error("TDomain::slice_index(t): t = " + number_text(t) + " is outside the domain [" + number_text(times_.front()) +
                ", " + number_text(times_.back()) + "]");
  }
  const std::size_t k = detail::first_time_after(times_, t) - 1;  // t_k <= t < t_k+1
  return std::min(k, nb_slices() - 1);
}

std::ptrdiff_t TDomain::time_index(double t) const {
  const std::size_t k = detail::first_time_from(times_, t);
  if (k == times_.size() || times_[k] != t) return -1;
  return static_cast<std::ptrdiff_t>(k);
}

Interval TDomain::slice_domain(std::size_t k) const {
  if (k >= nb_slices()) {
    throw OutOfRangeError("TDomain::slice_domain(k): slice " + std::to_string(k) + " out of range [0, " +
                std::to_string(nb_slices()) + ")");
  }
  return {times_[k], times_[k + 1]};
}

Interval TDomain::slice_width(std::size_t k) const {
  if (k >= nb_slices()) {
    throw OutOfRangeError("TDomain::slice_width(k): slice " + std::to_string(k) + " out of range [0, " +
                std::to_string(nb_slices()) + ")");
  }
  return Interval(times_[k + 1]) - Interval(times_[k]);
}

std::size_t TDomain::sample(double t) {
  if (std::isnan(t)) throw Error("TDomain::sample(t): t is NaN");
  if (!(t >= times_.front() && t <= times_.back())) {
    throw Error("TDomain::sample(t): t = " + number_text(t) + " is outside the domain [" + number_text(times_.front()) + ", " +
                number_text(times_.back()) + "]");
  }
  const std::ptrdiff_t existing = time_index(t);
  if (existing >= 0) return static_cast<std::size_t>(existing);
  const std::size_t k = slice_index(t);
  std::lock_guard<std::mutex> lock(mutex_);
  times_.insert(times_.begin() + static_cast<std::ptrdiff_t>(k) + 1, t);
  for_each_attached([k](TubeData& d) { d.split(k); });
  return k + 1;
}

template <class F>
void TDomain::for_each_attached(F&& f) {
  std::erase_if(attached_, [](const std::weak_ptr<TubeData>& w) { return w.expired(); });
  for (const auto& w : attached_) {
    if (auto data = w.lock()) f(*data);
  }
}

std::size_t TDomain::extend(double t) {
  if (!std::isfinite(t)) throw Error("TDomain::extend(t): t = " + number_text(t) + " is not finite");
  if (!(t > times_.back())) {
    throw Error("TDomain::extend(t): t = " + number_text(t) + " is not after the end of the domain t_N = " +
                number_text(times_.back()));
  }
  std::lock_guard<std::mutex> lock(mutex_);
  times_.push_back(t);
  for_each_attached([](TubeData& d) { d.append(); });
  return nb_slices();
}

std::size_t TDomain::forget_before(double t) {
  if (std::isnan(t)) throw Error("TDomain::forget_before(t): t is NaN");
  if (t < times_.front()) return 0;
  // Slices k < m end at t_{k+1} <= t; the last slice always stays.
  const std::size_t m = std::min(detail::first_time_after(times_, t) - 1, nb_slices() - 1);
  if (m == 0) return 0;
  std::lock_guard<std::mutex> lock(mutex_);
  times_.erase(times_.begin(), times_.begin() + static_cast<std::ptrdiff_t>(m));
  for_each_attached([m](TubeData& d) { d.drop_front(m); });
  forgotten_ += m;
  return m;
}

void TDomain::sample(const Interval& t) {
  if (t.is_empty()) return;
  if (!t.intersects(t0_tf())) {
    throw Error("TDomain::sample(t): [t] = " + t.str() + " does not meet the domain " + t0_tf().str());
  }
  for (const double b : {t.lb(), t.ub()}) {
    if (b > times_.front() && b < times_.back()) sample(b);
  }
}

std::size_t TDomain::nb_attached() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<std::size_t>(
      std::count_if(attached_.begin(), attached_.end(), [](const auto& w) { return !w.expired(); }));
}

void TDomain::attach(const std::shared_ptr<TubeData>& data) {
  if (!data || data->slices.size() != nb_slices() || data->gates.size() != nb_slices() + 1) {
    throw DimensionError("TDomain::attach: tube data of " + std::to_string(data ? data->slices.size() : 0) +
                         " slices does not match the " + std::to_string(nb_slices()) + " slices of the domain");
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (attached_.size() >= prune_at_) {  // amortized purge of destroyed tubes
    std::erase_if(attached_, [](const std::weak_ptr<TubeData>& w) { return w.expired(); });
    prune_at_ = std::max<std::size_t>(16, 2 * attached_.size());
  }
  attached_.push_back(data);
}

void slice_range(const TDomain& td, const Interval& t, std::size_t& first, std::size_t& last, const char* where) {
  if (t.is_empty() || !t.is_subset(td.t0_tf())) {
    throw Error(std::string(where) + ": [t] = " + t.str() + " is " + (t.is_empty() ? "empty" : "not inside ") +
                (t.is_empty() ? "" : td.t0_tf().str()));
  }
  const auto ts = td.times();
  const std::size_t n = td.nb_slices();
  if (t.is_degenerate()) {
    const std::ptrdiff_t g = td.time_index(t.lb());
    if (g < 0) {
      first = last = td.slice_index(t.lb());
    } else {
      const auto k = static_cast<std::size_t>(g);
      first = k > 0 ? k - 1 : 0;
      last = std::min(k, n - 1);
    }
    return;
  }
  // Slices with t_k < t⁺ and t_{k+1} > t⁻.
  first = detail::first_time_after(ts, t.lb()) - 1;
  last = detail::first_time_from(ts, t.ub()) - 1;
}

}  // namespace sillage
