#pragma once
// Problem: an estimation problem as declared in a TOML file (docs/cli.md),
// after parsing and validation (load_problem.h) and before any domain exists
// (build_network.h builds them). Everything keeps its place in the file, so
// later errors (a CSV row, an empty result) can point back at it.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sillage/io/csv.h"
#include "sillage/problem/problem_error.h"

namespace sillage {

struct TimeSpec {
  double t0 = 0, tf = 0;
  std::optional<double> delta;  // none: "auto"
  SourcePos pos;
};

struct DataSpec {
  std::string name, path;  // path resolved against the problem's directory
  CsvTable table;
  SourcePos pos;
};

enum class VarKind { Tube, TubeVector, Interval, Box };

// A bound of one component: an expression of t (tubes) or a constant
// expression (intervals, boxes), rigorous: "0.1" encloses 1/10. Empty: the
// whole line.
struct BoundSpec {
  std::string expr;
  SourcePos pos;
};

// A value at a time point (a gate), e.g. the initial condition x(0) in [x0].
struct GateSpec {
  double t = 0;
  std::vector<BoundSpec> value;  // one per component
  SourcePos pos;
};

struct VarSpec {
  std::string name;
  VarKind kind = VarKind::Tube;
  std::size_t dim = 1;
  std::vector<BoundSpec> value;  // one per component
  std::vector<GateSpec> at;      // tubes only
  SourcePos pos;
  bool is_tube() const { return kind == VarKind::Tube || kind == VarKind::TubeVector; }
};

enum class ConstraintKind { Expr, Deriv, Increment, Eval };

struct ConstraintSpec {
  ConstraintKind kind = ConstraintKind::Expr;
  std::string label;  // "constraint 2 (deriv x' = v)", for the reports
  // Expr: expr = 0 at every time (tubes) or once (intervals, boxes);
  // components written x[i] (0-based).
  // Eval: the observation of one row, over the evaluated value (written as
  // the tube's name), the row's columns and other variables.
  std::string expr;
  SourcePos expr_pos;
  std::string x, v;  // Deriv: x' = v; Increment: x(t_{k+1}) - x(t_k) in v(k); Eval: y, y' = v
  // Eval: one CtcEval per row of `data`, at time column `time` ± time_error;
  // each column c of `errors` is c ± errors[c] (other columns: exact). The
  // errors are kept as written (decimal text), enclosed rigorously.
  std::string data, time_column;
  std::string time_error = "0";
  std::map<std::string, std::string> errors;
  SourcePos pos;
};

struct TruthSpec {
  std::string data, time_column;
  std::map<std::string, std::vector<std::string>> columns;  // variable -> one column per component
  SourcePos pos;
};

struct OutputSpec {
  std::vector<double> times;                             // results table rows
  std::vector<std::pair<std::string, std::size_t>> plot_tubes;  // variable, component; empty: all
  std::vector<std::pair<std::string, std::pair<std::size_t, std::size_t>>> maps;  // variable, (i, j)
  std::optional<TruthSpec> truth;
};

struct Problem {
  std::string file, text;  // the path as given, and its text
  std::string hash;        // FNV-1a 64 of the text, hex
  TimeSpec time;
  std::vector<DataSpec> data;
  std::vector<VarSpec> vars;
  std::vector<ConstraintSpec> constraints;
  OutputSpec output;

  const VarSpec* var(const std::string& name) const;
  const DataSpec* table(const std::string& name) const;
};

const char* kind_name(VarKind k);
const char* kind_name(ConstraintKind k);

}  // namespace sillage
