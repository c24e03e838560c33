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

// sqr of a trajectory (composite).
Trajectory sqr(const Trajectory& x);
// sqrt of a trajectory (composite).
Trajectory sqrt(const Trajectory& x);
// exp of a trajectory (composite).
Trajectory exp(const Trajectory& x);
// log of a trajectory (composite).
Trajectory log(const Trajectory& x);
// sin of a trajectory (composite).
Trajectory sin(const Trajectory& x);
// cos of a trajectory (composite).
Trajectory cos(const Trajectory& x);
// tan of a trajectory (composite).
Trajectory tan(const Trajectory& x);
// atan of a trajectory (composite).
Trajectory atan(const Trajectory& x);
// abs of a trajectory (composite).
Trajectory abs(const Trajectory& x);
Trajectory atan2(const Trajectory& y, const Trajectory& x);  // atan2(y, x), y first (composite)

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
  // Analytic: a vector expression of t, e.g. '(cos(t), sin(t))', over the domain.
  TrajectoryVector(const std::string& expr_of_t, const Interval& domain);

  // The dimension n.
  std::size_t size() const { return x_.size(); }
  const Trajectory& operator[](std::size_t i) const;  // Error if i >= size()
  Trajectory& operator[](std::size_t i);
  const std::vector<Trajectory>& components() const { return x_; }
  // The intersection of the components' domains.
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
