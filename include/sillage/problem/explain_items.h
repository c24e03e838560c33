#pragma once
// The statements of a problem file that sillage explain may relax (its
// items, explain_empty.h), and the problem with some of them relaxed: a bound
// becomes the whole line; a gate, a table of slices or gates, a constraint,
// or an eval's rows (all of them, or a run of them) are dropped. Each
// relaxation only removes what the file states, so the relaxed problem's
// solutions include the problem's.
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/problem/problem.h"

namespace sillage {

// What a statement of the file is, hence how it is relaxed.
enum class ItemKind {
  Bound,       // a variable's `value`, one component: the whole line instead
  Gate,        // an `at` entry of a tube: dropped
  TableBound,  // a tube's `slices` or `gates` from a table: dropped
  Constraint,  // a [[constraint]] other than an eval: dropped
  Rows,        // an eval's rows, all of them or a run of them: dropped
};

// The name of an item kind: "bound", "gate", "table bound", "constraint", "rows".
const char* kind_name(ItemKind k);

// One statement of the file that the explanation may relax.
struct ExplainItem {
  // What is relaxed.
  ItemKind kind = ItemKind::Bound;
  // The statement as the file writes it: "[var.psi] at t = 3856.8573", "[var.p] value[1]",
  // "[var.dpsi] slices from odometry", "constraint 4 (heading): ...", "ranges lines 120 to 239 (120 rows of constraint 9 (eval), ranges.csv:120-239)".
  std::string label;
  // Where the file states it.
  SourcePos pos;
  // The bound's or gate's text as written ("-2.060753 + [-0.05, 0.05]"); "" for constraints and rows.
  std::string stated;
  // Bound, Gate, TableBound: the variable.
  std::string var;
  // Bound: the component; Gate: the entry of `at`; TableBound: 0 slices, 1 gates; Constraint, Rows: the constraint (file order).
  std::size_t index = 0;
  // Rows: the first table row dropped.
  std::size_t first_row = 0;
  // Rows: the table row after the last one dropped (rows [first_row, last_row); the kept rows only).
  std::size_t last_row = 0;
  // Rows: the number of rows of the eval kept in that run.
  std::size_t nb_rows = 0;
  // Gate: its time as written (between two doubles); Rows: the hull of the rows' times; else empty.
  Interval time = Interval::empty();
  // Rows: true for every row of the eval (the constraint dropped), false for a run of them.
  bool all_rows = true;
  // "label (file:line)".
  std::string str() const;
};

// The items of p that explain_empty may relax, in file order.
std::vector<ExplainItem> explain_items(const Problem& p);

// The kept rows of a Rows item of p in `parts` runs of about as many rows (fewer when it has
// fewer rows), each a Rows item labelled by its lines in the table's file ("ranges lines 2 to 6
// (5 rows of constraint 4 (eval), ranges.csv:2-6)").
std::vector<ExplainItem> row_runs(const Problem& p, const ExplainItem& rows, std::size_t parts);

// p with the items relaxed (indices into `items`).
Problem relaxed_problem(const Problem& p, const std::vector<ExplainItem>& items,
                        const std::vector<std::size_t>& relaxed);

}  // namespace sillage
