#pragma once
// The inside of OnlineProblem (online_problem.h), shared by its files: the
// model declared from the file (online_problem_model.cpp), the rows fed
// (online_problem.cpp) and the rows recorded (recorded_rows.cpp). Internal.
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "sillage/ctc/ctc.h"
#include "sillage/expr/function.h"
#include "sillage/problem/online_problem.h"
#include "sillage/problem/var_refs.h"

namespace sillage::detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// What cannot run online, at its place in the file.
ProblemError not_online(const SourcePos& pos, const std::string& found, const std::string& why);

// A tube's bound, "(e1, e2, ...)" of t ("" components free), or none when no component is bounded.
std::optional<Function> bound_of(const VarSpec& v);

// An eval constraint's observation of one row: its function over (z, the row's values).
struct EvalPlan {
  const ConstraintSpec* c = nullptr;
  std::shared_ptr<const Ctc> obs;                // CtcFunction over the references in order
  std::shared_ptr<const std::vector<int>> slots;  // per reference: its component of z, or -1 (a measured value)
  std::vector<std::string> measured;             // the columns of the -1 references, in order
  std::size_t nz = 0;                            // components of z: the evaluated tubes' together
  Interval terr;
  std::map<std::string, Interval> errors;
  std::map<double, std::size_t> join_rows;  // join_on value -> row of the joined table
};

// An observation waiting for time to reach its start.
struct Waiting {
  Interval t;
  std::vector<std::string> states;
  std::shared_ptr<const Ctc> ctc;
};

// The inside of an OnlineProblem.
struct OnlineProblemImpl {
  const Problem p;  // a copy: the tables the rows are read against, for the estimator's life
  std::unique_ptr<OnlineEstimator> est;
  std::vector<std::string> outputs;
  std::string clock;  // the table whose rows are the periods ("": the points table or δ)
  std::vector<const VarSpec*> inputs;  // tubes whose slices come from the clock table
  std::vector<Function> input_values;  // per input: its value over (the clock's columns, dt)
  std::vector<std::optional<Function>> input_bounds;  // per input: its bound of t, if any
  std::map<std::string, std::vector<EvalPlan>> evals;  // per table
  std::vector<Waiting> waiting;
  std::map<std::string, std::set<std::string>> needed;  // per table: the columns its rows must give
  std::function<void()> updated;
  std::size_t reported = 0;  // the estimator's updates when the last estimate was reported
  double delta = 0;         // the slice width of a δ problem (0: time points)
  std::size_t ticks = 0;    // grid points passed (δ)

  explicit OnlineProblemImpl(const Problem& problem) : p(problem) {}

  // The model (online_problem_model.cpp).
  void declare_vars();
  void parse_inputs();
  void declare_constraints();
  bool implied_deriv(const std::string& y) const;
  void plan_eval(const ConstraintSpec& c, std::set<std::string>& with_deriv);
  std::string ref_name(const VarRef& r, const SourcePos& pos) const;
  // The rows (online_problem.cpp).
  std::vector<double> values_of(const StreamRow& row) const;
  void advance(double t, const std::vector<std::pair<std::string, IntervalVector>>& given);
  void report();
  void release();
  void tick(double t);
  void clock_row(const StreamRow& row, const std::vector<double>& values);
  void observation_rows(const StreamRow& row, const std::vector<double>& values);
};

}  // namespace sillage::detail
