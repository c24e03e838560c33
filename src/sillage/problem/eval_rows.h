#pragma once
// The rows of an eval constraint: which are kept and at what time (internal;
// shared by load_eval.cpp, which checks the times against [t0, tf], and
// build_network.cpp, which builds a CtcEval per row or a CtcEvalList of them).
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "sillage/ctc/ctc.h"
#include "sillage/expr/function.h"
#include "sillage/interval/interval.h"
#include "sillage/io/csv.h"
#include "sillage/problem/problem.h"
#include "sillage/problem/problem_error.h"
#include "sillage/problem/var_refs.h"

namespace sillage::detail {

// A CSV cell as written: its decimal text is within half an ulp of the
// double read, so the double's neighbours enclose it.
Interval csv_cell(double d);
// The shortest text that reads back as d ("13.3", where number_text gives 17
// digits): a cell as written, for messages.
std::string cell_text(double d);

// The indices of f's variables that its expressions read: a table's row is
// converted to intervals only in the columns an expression uses (plaza1's
// odometry has 8 columns, its expressions read one), and a streamed row
// needs only those.
std::vector<std::size_t> read_vars(const Function& f);

// The first row c keeps whose join key is in no row of the joined table: an
// error at c's join, naming the row's file and line; none if c has no join.
void check_join_keys(const ConstraintSpec& c, const CsvTable& table, const CsvTable& joined, const SourcePos& at);

// True if the row passes the constraint's `where` filter.
bool eval_row_kept(const ConstraintSpec& c, const CsvTable& table, std::span<const double> values);

// The time of a row: the stamp ± terr, or [lb, ub] ± terr, or the whole
// domain (no time column: unknown), within the domain (empty: outside it).
Interval eval_row_time(const ConstraintSpec& c, const CsvTable& table, std::span<const double> values,
                       const Interval& terr, const Interval& domain);

// The observation of eval constraint c rewritten over its names: the tubes
// of c.ys, the columns of its table (and of the joined one), and the
// problem's other variables (ProblemError for an unknown name).
RewrittenExpr eval_observation(const Problem& p, const ConstraintSpec& c);

// The tubes j of eval c whose y' = vs[j] no deriv constraint of p states: the
// eval adds a CtcDeriv for each (build_network), which `sillage check` counts.
std::vector<std::size_t> implied_derivs(const Problem& p, const ConstraintSpec& c);

// True when the rows of c are one CtcEvalList (build_network, and `sillage
// check`'s count): one tube with its derivative, and an observation r over
// that tube and the row's columns only.
bool eval_rows_listed(const Problem& p, const ConstraintSpec& c, const RewrittenExpr& r);

// The groups of an eval's kept rows that each hold at most c.q wrong ones
// (indices into row_times, the kept rows' times in order): all of them, or
// those stamped (the middle of their time) in each window [s0 + kW/2,
// s0 + kW/2 + W] (q_window), or rows [kM/2, kM/2 + M) (q_rows). A group of
// q rows or fewer is left out: all of them may be wrong, it states nothing.
std::vector<std::vector<std::size_t>> outlier_groups(const ConstraintSpec& c, const std::vector<Interval>& row_times);

// A row's observation as a contractor on z alone (the fix of CtcEvalList):
// the constraint's contractor acts on its references in order, each either a
// component of z (slot >= 0) or the next of the row's measured values
// (slot -1), which stay constants here.
class RowObservation : public Ctc {
 public:
  RowObservation(std::shared_ptr<const Ctc> obs, std::shared_ptr<const std::vector<int>> slots, std::size_t nz,
                 IntervalVector values);
  std::string name() const override { return obs_->name(); }
  std::string describe() const override { return obs_->describe(); }
  void contract(IntervalVector& z) const override;

 private:
  std::shared_ptr<const Ctc> obs_;
  std::shared_ptr<const std::vector<int>> slots_;  // shared by the rows of a constraint
  IntervalVector values_;
};

}  // namespace sillage::detail
