#pragma once
// Why a problem has no solution, in terms the user can act on: a small set
// of the file's statements (a variable's bound, a gate `at`, a slices or
// gates table, a constraint, an eval's rows) whose relaxation leaves the
// contraction non-empty. The contractor that emptied a domain last is often
// far from the cause (a wrong start heading is found out by a range 25 s
// later); relaxing the statements one at a time finds the cause instead.
//
// Relaxing an item: a bound becomes the whole line, a gate or a table of
// slices or gates is dropped, a constraint is dropped, an eval's rows (all
// of them, or a run of them) are dropped. Each trial is a contraction of the
// relaxed problem at one δ (the failing solve's), with its own budget.
//
// The search: each item alone first (in parallel, oneTBB); every item whose
// relaxation leaves the contraction non-empty is an explanation, ranked
// (below); an eval whose rows are blamed is narrowed to a run of its rows by
// bisection. If no item alone does, a set: FastDiag (Felfernig et al. 2012,
// a divide and conquer over the items, the most trusted kept longest) finds
// one whose relaxation is non-empty, then each of its items is put back
// alone to check that it is needed (Relaxation::minimal).
//
// What it means: a relaxation "restores" when its contraction is not empty:
// no contradiction found, which is necessary for a solution, not sufficient
// (a contraction encloses the solutions; it may be non-empty with none).
// The values it proves for the relaxed bound or gate (ProvenValue) are
// guaranteed: every solution of the relaxed problem lies in them. Disjoint
// from the stated value: given the rest of the file, that value is impossible.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/problem/explain_items.h"
#include "sillage/problem/solve_problem.h"

namespace sillage {

// What the relaxed problem's contraction proves of a relaxed bound or gate (one component).
struct ProvenValue {
  // "psi(3856.8573)", "p[1](3856.8573)", "omega over [t0, tf]", "k".
  std::string what;
  // The file's value there (an expression of t: its range over [t0, tf]).
  Interval stated;
  // The relaxed problem's domain there: every solution of the relaxed problem with its value in
  // `window` has it in `proven`.
  Interval proven;
  // Where the value was searched: the whole line when the relaxed contraction bounds it; else
  // (a gate left unbounded, e.g. a heading: the contraction cannot invert cos and sin over the
  // whole line) the stated value widened 64 times, at least ±π, cut in 16 cells each contracted
  // with the gate stated there, a cell not proven empty halved down to the stated value's width
  // (probing); `proven` is then the hull of the cells' contractions.
  Interval window;
  // Probed: the cells' contractions as a union of disjoint intervals in increasing order (a
  // heading is often consistent near two values a turn apart); empty when not probed.
  std::vector<Interval> pieces;
  // True when stated meets neither proven nor a piece: given the rest of the file, the stated value is impossible.
  bool disjoint() const;
  // The proven set in words, rounded outward: the pieces joined by ∪, or proven ("[-2.1, -0.9] ∪ [2.9, 4.3]").
  std::string proven_text() const;
};

// A set of items whose relaxation leaves the contraction non-empty.
struct Relaxation {
  // Indices into Explanation::items.
  std::vector<std::size_t> items;
  // Per relaxed bound or gate component: what the relaxed contraction proves of it.
  std::vector<ProvenValue> values;
  // Every item was checked to be needed: with any one of them put back, the contraction is empty again.
  bool minimal = false;
  // Its trial's wall-clock time.
  double seconds = 0;
};

// How a trial (a contraction of the problem with some items relaxed) ended.
enum class TrialOutcome {
  Empty,     // still empty: the relaxation does not remove the contradiction
  NotEmpty,  // no contradiction found
  Stopped,   // its budget (or the search's time) ran out first: undecided
};

// The name of a trial outcome: "empty", "not empty", "stopped".
const char* outcome_name(TrialOutcome o);

// One trial of the search.
struct ExplainTrial {
  // The items relaxed (indices into Explanation::items).
  std::vector<std::size_t> items;
  // How its contraction ended.
  TrialOutcome outcome = TrialOutcome::Empty;
  // Its wall-clock time.
  double seconds = 0;
  // A probe of a gate's value (ProvenValue::window): the component and the cell, e.g.
  // "psi(3856.8573) in [0.6, 1]"; "" for a relaxation.
  std::string probe;
  // Why the relaxed problem could not be solved (an Error of its build: outcome Stopped); "" otherwise.
  std::string error;
};

// How explain_empty searches: the trials' δ and budgets, the narrowing of rows.
struct ExplainOptions {
  // The δ of the trials; none: the one at which the problem's solve emptied (its last step).
  std::optional<double> delta;
  // The order within a round; none: the file's.
  std::optional<Scheduling> scheduling;
  // Wall-clock seconds of the whole search (its trials share them); 0: no limit.
  double max_seconds = 30;
  // Narrow a blamed eval's rows to a run of them (bisection into 4 runs at each step).
  bool refine_rows = true;
  // Stop narrowing at runs of at most this many rows (>= 1).
  std::size_t min_rows = 1;
  // The budget of each trial's contraction: max_boxes (contractor runs), max_seconds (0: the
  // search's time left), cancel (Cancelled out of explain_empty; Python: Ctrl-C).
  Budget budget;
};

// The answer: the items, the explanations found, the trials run.
struct Explanation {
  // True when the problem's contraction is empty (something to explain); false: no contradiction
  // found in the problem as given, nothing to explain (or its solve stopped: `stopped` says).
  bool empty = false;
  // The failing solve's explanation (the contractor that emptied a domain, and where).
  std::string why_empty;
  // The δ of the trials (a problem on a table's time points: their mean period).
  double delta = 0;
  // The slices of the trials.
  std::size_t slices = 0;
  // Every statement that may be relaxed, in file order, then the runs of rows found.
  std::vector<ExplainItem> items;
  // The explanations found, best first: those where the relaxed problem proves a stated value
  // impossible, then those that bound every relaxed value, then those without values
  // (constraints, rows), then those leaving a relaxed value unbounded (the contradiction goes
  // only if it may be anything); then fewer items first, then gates, runs of rows, bounds,
  // tables of bounds, whole evals, constraints; then file order.
  std::vector<Relaxation> relaxations;
  // Every trial, in the order they were decided.
  std::vector<ExplainTrial> trials;
  // True when the search ran every trial it planned; false: `stopped` says why.
  bool complete = false;
  // Why the search is partial ("" when complete): the time spent, the trials left.
  std::string stopped;
  // Wall-clock time of the search (the problem's own solve included when explain_empty ran it).
  double seconds = 0;
  // The explanation in words, one item per line, as `sillage solve` and `sillage explain` print it.
  std::string str() const;
};

// Solves p (at options.delta, or the file's δ, or the automatic one) and, when its contraction is
// empty, searches for the relaxations (GIL released in Python). Error for bad options.
Explanation explain_empty(const Problem& p, const ExplainOptions& options = {});

// The explanation as JSON (results.json's "explanation"): empty, why_empty, delta, slices,
// complete, stopped, seconds, the number of trials, and per relaxation its items (label, kind,
// file, line, stated, time) and proven values (what, stated, proven, window as [lb, ub], null bounds when
// unbounded, null when empty; disjoint), best first.
std::string explanation_json(const Explanation& e);

// The same from the problem's failing solve `failed` (its last step's δ), not solved again.
Explanation explain_empty(const Problem& p, const SolveResult& failed, const ExplainOptions& options = {});

}  // namespace sillage
