#include "sillage/tube/trajectory_arithmetic.h"

#include <utility>

#include "sillage/error.h"
#include "sillage/interval/elementary.h"

namespace sillage {

namespace {

Interval common_domain(const Interval& a, const Interval& b, const char* where) {
  const Interval d = a & b;
  if (d.is_empty()) {
    throw Error(std::string(where) + ": the domains " + a.str() + " and " + b.str() + " do not overlap");
  }
  return d;
}

template <class Op>
Trajectory unary(const Trajectory& x, Op op) {
  return Trajectory([x, op](const Interval& t) { return op(x(t)); }, x.domain());
}

template <class Op>
Trajectory binary(const Trajectory& x, const Trajectory& y, Op op, const char* where) {
  const Interval d = common_domain(x.domain(), y.domain(), where);
  return Trajectory([x, y, op](const Interval& t) { return op(x(t), y(t)); }, d);
}

template <class Op>
Trajectory with_number(const Trajectory& x, double y, Op op) {
  const Interval c(y);  // Error if y is not finite
  return Trajectory([x, c, op](const Interval& t) { return op(x(t), c); }, x.domain());
}

}  // namespace

Trajectory operator-(const Trajectory& x) { return unary(x, [](const Interval& a) { return -a; }); }

#define SILLAGE_TRAJ_OP(op)                                                                                  \
  Trajectory operator op(const Trajectory& x, const Trajectory& y) {                                         \
    return binary(x, y, [](const Interval& a, const Interval& b) { return a op b; }, "Trajectory " #op);    \
  }                                                                                                          \
  Trajectory operator op(const Trajectory& x, double y) {                                                    \
    return with_number(x, y, [](const Interval& a, const Interval& b) { return a op b; });                  \
  }                                                                                                          \
  Trajectory operator op(double x, const Trajectory& y) {                                                    \
    return with_number(y, x, [](const Interval& a, const Interval& b) { return b op a; });                  \
  }
SILLAGE_TRAJ_OP(+)
SILLAGE_TRAJ_OP(-)
SILLAGE_TRAJ_OP(*)
SILLAGE_TRAJ_OP(/)
#undef SILLAGE_TRAJ_OP

#define SILLAGE_TRAJ_FN(f) \
  Trajectory f(const Trajectory& x) { return unary(x, [](const Interval& a) { return sillage::f(a); }); }
SILLAGE_TRAJ_FN(sqr)
SILLAGE_TRAJ_FN(sqrt)
SILLAGE_TRAJ_FN(exp)
SILLAGE_TRAJ_FN(log)
SILLAGE_TRAJ_FN(sin)
SILLAGE_TRAJ_FN(cos)
SILLAGE_TRAJ_FN(tan)
SILLAGE_TRAJ_FN(atan)
SILLAGE_TRAJ_FN(abs)
#undef SILLAGE_TRAJ_FN

Trajectory atan2(const Trajectory& y, const Trajectory& x) {
  return binary(y, x, [](const Interval& a, const Interval& b) { return sillage::atan2(a, b); }, "atan2");
}

// ---- TrajectoryVector ----

TrajectoryVector::TrajectoryVector(std::vector<Trajectory> xs) : x_(std::move(xs)) {
  if (x_.empty()) throw DimensionError("TrajectoryVector: no component");
  domain_ = x_.front().domain();
  for (std::size_t i = 1; i < x_.size(); ++i) {
    const Interval d = domain_ & x_[i].domain();
    if (d.is_empty()) {
      throw Error("TrajectoryVector: component " + std::to_string(i) + " (domain " + x_[i].domain().str() +
                  ") does not overlap the others (" + domain_.str() + ")");
    }
    domain_ = d;
  }
}

namespace {

std::vector<Trajectory> sampled_components(const std::vector<double>& times,
                                           const std::vector<std::vector<double>>& values) {
  if (times.size() != values.size()) {
    throw DimensionError("TrajectoryVector(times, values): " + std::to_string(times.size()) + " times but " +
                         std::to_string(values.size()) + " points");
  }
  if (values.empty()) throw Error("TrajectoryVector(times, values): no sample");
  const std::size_t n = values.front().size();
  if (n == 0) throw DimensionError("TrajectoryVector(times, values): points of dimension 0");
  std::vector<std::vector<double>> cols(n, std::vector<double>(values.size()));
  for (std::size_t j = 0; j < values.size(); ++j) {
    if (values[j].size() != n) {
      throw DimensionError("TrajectoryVector(times, values): point " + std::to_string(j) + " has " +
                           std::to_string(values[j].size()) + " values, point 0 has " + std::to_string(n));
    }
    for (std::size_t i = 0; i < n; ++i) cols[i][j] = values[j][i];
  }
  std::vector<Trajectory> xs;
  for (auto& c : cols) xs.emplace_back(times, c);
  return xs;
}

std::vector<Trajectory> analytic_components(const Function& f, const Interval& domain) {
  if (f.nb_vars() != 1) throw DimensionError("TrajectoryVector(f, domain): f must be a function of one variable t");
  std::vector<Trajectory> xs;
  if (f.image_dim() == 1) {
    xs.emplace_back(f, domain);
  } else {
    for (std::size_t i = 0; i < f.image_dim(); ++i) xs.emplace_back(f[i], domain);
  }
  return xs;
}

}  // namespace

TrajectoryVector::TrajectoryVector(const std::vector<double>& times, const std::vector<std::vector<double>>& values)
    : TrajectoryVector(sampled_components(times, values)) {}

TrajectoryVector::TrajectoryVector(const Function& f, const Interval& domain)
    : TrajectoryVector(analytic_components(f, domain)) {}

TrajectoryVector::TrajectoryVector(const std::string& expr_of_t, const Interval& domain)
    : TrajectoryVector(Function({"t"}, expr_of_t), domain) {}

const Trajectory& TrajectoryVector::operator[](std::size_t i) const {
  if (i >= x_.size()) {
    throw OutOfRangeError("TrajectoryVector[i]: i = " + std::to_string(i) + " >= size " + std::to_string(x_.size()));
  }
  return x_[i];
}

Trajectory& TrajectoryVector::operator[](std::size_t i) {
  return const_cast<Trajectory&>(static_cast<const TrajectoryVector&>(*this)[i]);
}

IntervalVector TrajectoryVector::operator()(double t) const {
  IntervalVector r(x_.size());
  for (std::size_t i = 0; i < x_.size(); ++i) r[i] = x_[i](t);
  return r;
}

IntervalVector TrajectoryVector::operator()(const Interval& t) const {
  IntervalVector r(x_.size());
  for (std::size_t i = 0; i < x_.size(); ++i) r[i] = x_[i](t);
  return r;
}

namespace {

template <class F>
TrajectoryVector map_components(std::size_t n, F f) {
  std::vector<Trajectory> xs;
  xs.reserve(n);
  for (std::size_t i = 0; i < n; ++i) xs.push_back(f(i));
  return TrajectoryVector(std::move(xs));
}

void check_sizes(const TrajectoryVector& x, const TrajectoryVector& y, const char* where) {
  check_same_size(x.size(), y.size(), where);  // interval_vector.h
}

}  // namespace

TrajectoryVector operator-(const TrajectoryVector& x) {
  return map_components(x.size(), [&](std::size_t i) { return -x[i]; });
}
TrajectoryVector operator+(const TrajectoryVector& x, const TrajectoryVector& y) {
  check_sizes(x, y, "TrajectoryVector +");
  return map_components(x.size(), [&](std::size_t i) { return x[i] + y[i]; });
}
TrajectoryVector operator-(const TrajectoryVector& x, const TrajectoryVector& y) {
  check_sizes(x, y, "TrajectoryVector -");
  return map_components(x.size(), [&](std::size_t i) { return x[i] - y[i]; });
}
TrajectoryVector operator*(const TrajectoryVector& x, const Trajectory& y) {
  return map_components(x.size(), [&](std::size_t i) { return x[i] * y; });
}
TrajectoryVector operator*(const Trajectory& x, const TrajectoryVector& y) {
  return map_components(y.size(), [&](std::size_t i) { return x * y[i]; });
}
TrajectoryVector operator*(const TrajectoryVector& x, double y) {
  return map_components(x.size(), [&](std::size_t i) { return x[i] * y; });
}
TrajectoryVector operator*(double x, const TrajectoryVector& y) {
  return map_components(y.size(), [&](std::size_t i) { return x * y[i]; });
}
TrajectoryVector operator/(const TrajectoryVector& x, const Trajectory& y) {
  return map_components(x.size(), [&](std::size_t i) { return x[i] / y; });
}
TrajectoryVector operator/(const TrajectoryVector& x, double y) {
  return map_components(x.size(), [&](std::size_t i) { return x[i] / y; });
}

}  // namespace sillage
