#pragma once
// Trajectory: one scalar function of time, used as a ground truth and to
// build tubes. Three kinds:
//  - sampled: points (t_i, x_i), the trajectory being the piecewise-linear
//    interpolation between them (its domain is [t_first, t_last]);
//  - analytic: a Function of the single variable t over a given domain;
//  - composite: the result of trajectory arithmetic (trajectory_arithmetic.h),
//    x op y evaluated as [x](t) op [y](t) on the operands' enclosures.
// Evaluations return guaranteed enclosures (Interval), rounding included:
// an analytic value is an interval evaluation; a sampled value is the
// interpolation formula evaluated in interval arithmetic.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sillage/expr/function.h"
#include "sillage/interval/interval.h"

namespace sillage {

class Trajectory {
 public:
  // Sampled. Error if empty, if a time or value is NaN/infinite, or (vector
  // form) if the sizes differ (DimensionError) or times are not strictly
  // increasing.
  explicit Trajectory(const std::map<double, double>& samples);
  // Sampled: the values at the times (strictly increasing), linear in between.
  Trajectory(const std::vector<double>& times, const std::vector<double>& values);
  // Analytic over `domain` (bounded, non-empty). The expression / Function
  // must be scalar, of one variable (named t for the text form).
  Trajectory(const Function& f, const Interval& domain);
  // Analytic: an expression of t over the domain.
  Trajectory(const std::string& expr_of_t, const Interval& domain);
  // Composite over `domain` (bounded, non-empty): x([t]) = eval([t]), which
  // must enclose the values over [t] (used by trajectory_arithmetic.h).
  using Eval = std::function<Interval(const Interval&)>;
  Trajectory(Eval eval, const Interval& domain);

  // True for a sampled trajectory.
  bool is_sampled() const { return !f_ && !eval_; }
  // True for an analytic one (an expression of t); neither: a composite (arithmetic result).
  bool is_analytic() const { return static_cast<bool>(f_); }
  // The time domain, an Interval.
  Interval domain() const { return domain_; }
  const std::vector<double>& sample_times() const { return ts_; }   // sampled only
  const std::vector<double>& sample_values() const { return xs_; }  // sampled only

  // Enclosure of x(t). Error if t is NaN or outside the domain.
  Interval operator()(double t) const;
  // Enclosure of x([t]) = {x(t) : t in [t]} (sampled: hull of the linear
  // pieces, i.e. the values at the ends of [t] and the samples inside).
  // Empty [t] -> empty. Error if [t] is not inside the domain.
  Interval operator()(const Interval& t) const;

  // Adds the sample (t, x) (sampled trajectories only; replaces an existing t).
  void set(double t, double x);

 private:
  void check_time(double t, const char* where) const;
  Interval interpolate(std::size_t i, const Interval& t) const;  // on piece [t_i, t_{i+1}]

  std::vector<double> ts_, xs_;
  std::shared_ptr<Function> f_;  // analytic when set
  Eval eval_;                    // composite when set
  Interval domain_;
};

}  // namespace sillage
