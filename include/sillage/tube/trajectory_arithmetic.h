#pragma once
// Arithmetic on trajectories and TrajectoryVector (vector trajectories).
//
// x op y is a composite Trajectory over the intersection of the domains
// (Error if it is empty): its value over [t] is
// [x]([t]) op [y]([t]) in interval arithmetic, rounding included, so it
// encloses {x(t) op y(t) : t ∈ [t]} (over an interval of time it may be
// wider than that range: x and y are evaluated independently). A double
// converts to the constant trajectory. The operands are copied.
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/expr/function.h"
#include "sillage/interval/interval.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/trajectory.h"

namespace sillage {

Trajectory operator-(const Trajectory& x);
Trajectory operator+(const Trajectory& x, const Trajectory& y);
Trajectory operator-(const Trajectory& x, const Trajectory& y);
Trajectory operator*(const Trajectory& x, const Trajectory& y);
Trajectory operator/(const Trajectory& x, const Trajectory& y);
Trajectory operator+(const Trajectory& x, double y);
Trajectory operator-(const Trajectory& x, double y);
Trajectory operator*(const Trajectory& x, double y);
Trajectory operator/(const Trajectory& x, double y);
Trajectory operator+(double x, const Trajectory& y);
Trajectory operator-(double x, const Trajectory& y);
Trajectory operator*(double x, const Trajectory& y);
Trajectory operator/(double x, const Trajectory& y);

Trajectory sqr(const Trajectory& x);
Trajectory sqrt(const Trajectory& x);
Trajectory exp(const Trajectory& x);
Trajectory log(const Trajectory& x);
Trajectory sin(const Trajectory& x);
Trajectory cos(const Trajectory& x);
Trajectory tan(const Trajectory& x);
Trajectory atan(const Trajectory& x);
Trajectory abs(const Trajectory& x);
Trajectory atan2(const Trajectory& y, const Trajectory& x);  // y first

// n scalar trajectories x_1, ..., x_n, a vector trajectory over the
// intersection of their domains.
class TrajectoryVector {
 public:
  // At least one component (DimensionError otherwise); Error if the
  // intersection of the domains is empty.
  explicit TrajectoryVector(std::vector<Trajectory> xs);
  // Sampled: values[j] is the point (n values, the same n for all) at
  // times[j] (DimensionError if the counts differ); times as for Trajectory.
  TrajectoryVector(const std::vector<double>& times, const std::vector<std::vector<double>>& values);
  // Analytic: a Function of one variable t (component i = f[i]) or a vector
  // expression of t, "(e1, e2, ...)", over `domain`.
  TrajectoryVector(const Function& f, const Interval& domain);
  TrajectoryVector(const std::string& expr_of_t, const Interval& domain);

  std::size_t size() const { return x_.size(); }
  const Trajectory& operator[](std::size_t i) const;  // Error if i >= size()
  Trajectory& operator[](std::size_t i);
  const std::vector<Trajectory>& components() const { return x_; }
  Interval domain() const { return domain_; }

  IntervalVector operator()(double t) const;          // component-wise Trajectory::operator()(t)
  IntervalVector operator()(const Interval& t) const;  // component-wise x([t])

 private:
  std::vector<Trajectory> x_;
  Interval domain_;
};

// Component-wise (DimensionError if the sizes differ).
TrajectoryVector operator-(const TrajectoryVector& x);
TrajectoryVector operator+(const TrajectoryVector& x, const TrajectoryVector& y);
TrajectoryVector operator-(const TrajectoryVector& x, const TrajectoryVector& y);
// Every component with the scalar trajectory or number y.
TrajectoryVector operator*(const TrajectoryVector& x, const Trajectory& y);
TrajectoryVector operator*(const Trajectory& x, const TrajectoryVector& y);
TrajectoryVector operator*(const TrajectoryVector& x, double y);
TrajectoryVector operator*(double x, const TrajectoryVector& y);
TrajectoryVector operator/(const TrajectoryVector& x, const Trajectory& y);
TrajectoryVector operator/(const TrajectoryVector& x, double y);

}  // namespace sillage
