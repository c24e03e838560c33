#pragma once
// The files of a solved problem, for programs: DIR/results.json (the bounds
// at the gates and slices of every variable, the problem's hash, the
// schedule) and DIR/NAME.csv per tube (rows of t_lb, t_ub, then lb, ub per
// component: a gate row has t_lb = t_ub, a slice row spans its slice;
// unbounded ends written inf / -inf, read as such by numpy and pandas).
// In JSON an interval is [lb, ub], an unbounded end null, the empty set null.
//
// Outputs in proportion: a tube of more than OutputOptions::max_slices
// slices is written decimated, every g-th time point (g the least that keeps
// at most max_slices rows of slices) with, between two of them, the hull of
// the slices and gates there, still an enclosure of every solution; a
// group holding an empty slice or gate is written empty. results.json says
// so ("decimated": g; its "times" are the points kept). max_slices = 0
// writes every slice (sillage solve --full-tubes).
#include <cstddef>
#include <string>
#include <vector>

#include "sillage/problem/explain_empty.h"
#include "sillage/problem/solve_problem.h"

namespace sillage {

struct OutputOptions {
  // The most slice rows of a tube (10 000 by default: plaza1's 9657 are whole); 0: all of them.
  std::size_t max_slices = 10000;
};

// Every g-th of the n + 1 time points, and the last (g = 1: all of them), for o.max_slices.
std::size_t decimation(std::size_t n, const OutputOptions& o);

// The JSON text of results.json; with the explanation e of a result without solution, its
// "explanation" (explanation_json) and "before_empty" (whether the domains before the
// contradiction were kept).
std::string results_json(const Problem& p, const SolveResult& r, const OutputOptions& o = {},
                         const Explanation* e = nullptr);
// The CSV text of one tube variable.
std::string tube_csv(const VarDomain& v, const OutputOptions& o = {});
// The names of the files `sillage solve` writes into its directory for p:
// results.json, report.html, NAME.csv per tube variable (and NAME.tube with tube_files).
std::vector<std::string> output_names(const Problem& p, bool tube_files);
// Error if writing output_names(p, tube_files) into dir would overwrite an
// input of p (the problem file or a data table: e.g. --out at the problem's
// own folder, where a table shares a tube's name), naming both; nothing is written.
void check_output_dir(const Problem& p, const std::string& dir, bool tube_files);
// The same for the files `names` (sillage replay's: replay.html, online.jsonl, ...).
void check_output_dir(const Problem& p, const std::string& dir, const std::vector<std::string>& names);
// Writes results.json (with the explanation e, if given) and the CSV files into dir (created,
// check_output_dir first); Error if it cannot.
void write_results(const Problem& p, const SolveResult& r, const std::string& dir, const OutputOptions& o = {},
                   const Explanation* e = nullptr);

// Writes text to dir/name; Error naming the path if it cannot.
void write_text_file(const std::string& dir, const std::string& name, const std::string& text);

}  // namespace sillage
