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

#include "sillage/cn/scheduling.h"
#include "sillage/io/csv.h"
#include "sillage/problem/problem_error.h"

namespace sillage {

// The most slices a δ may give over [t0, tf] (the file's or one given beside it).
inline constexpr double kMaxSlices = 5e7;

struct TimeSpec {
  double t0 = 0, tf = 0;
  std::optional<double> delta;  // none: "auto" (or the time points of a table)
  // points = {data, column}: the time points are a table's column (strictly
  // increasing), one slice between consecutive stamps; no delta then.
  std::vector<double> points;
  std::string points_data;
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

// A value at a time, e.g. the initial condition x(0) in [x0]. The time as
// written is a decimal in [t_lo, t_hi] (the doubles around it; t_lo = t_hi =
// t when the double is the decimal itself): a gate then, else an evaluation
// at that time interval (build_network.h).
struct GateSpec {
  double t = 0, t_lo = 0, t_hi = 0;
  std::vector<BoundSpec> value;  // one per component
  SourcePos pos;
};

// The slices of a tube from a table (one row per slice of the time points of
// [time] points = {...}): `value` is an expression of the row's columns and
// dt (the slice's width), e.g. "delta_heading + dt*[-0.005, 0.005]". Or its
// gates (one row per time point): an expression of the row's columns, e.g.
// "v + [-0.01, 0.01]", the value measured at that time.
struct SliceDataSpec {
  std::string data;
  BoundSpec value;
  // held = true (slices only): the table is the [time] points' own, each row
  // held until the next (a command): N + 1 rows, slice k from row k.
  bool held = false;
};

struct VarSpec {
  std::string name;
  VarKind kind = VarKind::Tube;
  std::size_t dim = 1;
  std::vector<BoundSpec> value;  // one per component
  std::vector<GateSpec> at;      // tubes only
  std::optional<SliceDataSpec> slices;  // scalar tubes only, with time points from data
  std::optional<SliceDataSpec> gates;   // scalar tubes only, with time points from data
  // angle = true: a scalar tube whose values are known modulo 2π (a heading):
  // its deriv is CtcDerivAngle, its evals CtcEvalAngle, and an expression
  // reads it under sin/cos/tan or as a term of its top-level sum (the
  // equation is then modulo 2π). Its truth is checked modulo 2π.
  bool angle = false;
  std::string unit;  // as the file states it (unit = "m"), for the reports; "" if it does not
  SourcePos pos;
  bool is_tube() const { return kind == VarKind::Tube || kind == VarKind::TubeVector; }
};

enum class ConstraintKind { Expr, Deriv, Increment, Eval, Heading, SecondDeriv, HeadingWindow, PImpliesZ, Python };

struct ConstraintSpec {
  ConstraintKind kind = ConstraintKind::Expr;
  std::string label;  // "constraint 2 (deriv x' = v)", for the reports
  // Expr: expr = 0 at every time (tubes) or once (intervals, boxes);
  // components written x[i] (0-based).
  // Eval: the observation of one row, over the evaluated value (written as
  // the tube's name), the row's columns and other variables.
  std::string expr;
  SourcePos expr_pos;
  // Heading (CtcHeading): position p (tube_vector, dim 2), heading psi,
  // distance per slice dist, turn rate omega (tubes), track error (rad, as written).
  std::string p, psi, dist, omega, track = "0";
  // HeadingWindow (CtcHeadingWindow): p, psi, dist, omega and track as for
  // Heading, dpsi the heading increment per slice (a tube), windows of
  // `window` seconds, one every `stride` slices (0: a quarter of a window at
  // the mean slice width, at least 1), the turn acceleration bound
  // `turn_accel` (rad/s², as written; "": none).
  std::string dpsi, turn_accel;
  double window = 0;
  std::size_t stride = 0;
  // PImpliesZ (CtcPImpliesZ, the temporal SLAM's contractor, thesis (7.9)):
  // p(t1) = p(t2) => z(t1) = z(t2) with p' = w; p and w tubes of one kind
  // and dimension (1 or 2), z a tube or tube_vector; t-boxes of width eps;
  // fast: Alg. 14 (the hull of each loop component) instead of Alg. 13.
  std::string w, z;
  double eps = 0;
  bool fast = false;
  // Deriv: x' = v; Increment: x(t_{k+1}) - x(t_k) in v(k); SecondDeriv:
  // x'' in v (CtcSecondDeriv, v the acceleration bounds); Eval: ys[0], vs[0]
  std::string x, v;
  // Eval: per kept row of `data`, one time t_i and one CtcEval z = y(t_i) per
  // tube y of `ys` (with y' = vs[j] unless ""), all at the same t_i. t_i is
  // the stamp column ± time_error (one column), the hull of two columns
  // [lb, ub] ± time_error, or the whole time domain (no column: an unknown
  // time the observations contract). Each column c of `errors` is c ±
  // errors[c] (other columns: the cell as written, enclosed to one ulp). The
  // errors are kept as written (decimal text), enclosed rigorously. The rows
  // of one tube with its derivative, whose observation involves only that
  // tube and the row's columns, are one CtcEvalList (build_network).
  std::vector<std::string> ys, vs;
  std::string data;
  std::vector<std::string> time_columns;
  std::string time_error = "0";
  std::map<std::string, std::string> errors;
  // rows kept: lo <= column <= hi for every entry (column = value: lo = hi)
  std::map<std::string, std::pair<double, double>> where;
  // join = {data, on}: each row also has the columns of the row of table
  // join_data with the same value in column join_on (ranges -> beacons).
  std::string join_data, join_on;
  bool gates = false;                   // time points at the bounds of every t_i
  // Eval: a kept row whose time lies wholly outside [t0, tf] is an error
  // naming the file and row, unless skip_outside (outside = "skip"): then
  // it is skipped and counted in nb_outside (sillage check, the report, results.json).
  bool skip_outside = false;
  std::size_t nb_outside = 0;
  // Eval: outliers. q = N: at most N of the rows are wrong (a CtcQEval over
  // them, listed evals only); with q_window = W seconds, at most N among the
  // rows stamped in any W seconds, or with q_rows = M among any M
  // consecutive rows (one CtcQEval per half-overlapping window of them).
  std::optional<std::size_t> q;
  double q_window = 0;
  std::size_t q_rows = 0;
  // Python: the user's sillage.TubeCtc subclass `cls` of the module `module`
  // (imported with the problem file's folder first on the path), built as
  // cls(**params), on the tube variables `args` in order (python_constraint.h).
  std::string module, cls;
  std::vector<std::string> args;
  std::map<std::string, double> params;
  SourcePos pos;
};

struct TruthSpec {
  std::string data, time_column;
  std::map<std::string, std::vector<std::string>> columns;  // variable -> one column per component
  SourcePos pos;
};

// Fixed points drawn on every map (beacons, landmarks): one per row of a table.
struct LandmarksSpec {
  std::string data, x, y;  // the table and its two coordinate columns
  SourcePos pos;
};

// Loops of the path (thesis ch. 6): the t-plane of the velocity v (a 2-D
// tube vector), or of the position p and its derivative v (7.28) when p is
// given; paving down to eps (time units; default (tf - t0)/2000).
struct LoopsSpec {
  std::string v, p;
  std::optional<double> eps;
  SourcePos pos;
};

// A time of the results table as written: a decimal in [lo, hi], the doubles
// around the one read (t); lo = hi = t when it is that double.
struct OutputTime {
  double t = 0, lo = 0, hi = 0;
};

struct OutputSpec {
  std::vector<OutputTime> times;                         // results table columns
  std::vector<std::pair<std::string, std::size_t>> plot_tubes;  // variable, component; empty: all
  std::vector<std::pair<std::string, std::pair<std::size_t, std::size_t>>> maps;  // variable, (i, j)
  std::optional<TruthSpec> truth;
  std::optional<LandmarksSpec> landmarks;
  std::optional<LoopsSpec> loops;
};

// [network]: how the propagation runs. ratio: a contractor's arguments wake
// their other contractors when they shrank by more than this share (0: the
// true fixed point; none: the network's default). order: the order the
// constraints enter the network, hence their order in the first round and in
// the queue: "file" (as written), or "cost" (the cheap ones first: the
// evaluations, which touch a few slices, then the pointwise expressions, and
// the whole-tube contractors last). scheduling: the order within each round
// of the propagation, "fifo" (as woken) or "priority" (by expected
// contraction over cost, ContractorNetwork::set_scheduling): the same fixed
// point either way.
enum class ConstraintOrder { File, Cost };

struct NetworkSpec {
  std::optional<double> ratio;
  ConstraintOrder order = ConstraintOrder::File;
  Scheduling scheduling = Scheduling::Fifo;
  SourcePos pos;
};

// [online]: how `sillage stream` and `sillage replay` run the problem
// (online_problem.h, docs/online.md). window: the seconds of past kept
// (none: everything); forget_every: the past beyond it gathered before it is
// dropped (0: window / 8); lead: how far ahead of now an observation may be
// stamped (held until time reaches it, refused beyond); outputs: the tube
// variables written per update (empty: all); output_every: the seconds of
// time between two estimates written (0: after every advance).
struct OnlineSpec {
  std::optional<double> window;
  double forget_every = 0;
  double lead = 5;
  std::vector<std::string> outputs;
  double output_every = 0;
  SourcePos pos;
};

struct Problem {
  std::string file, text;  // the path as given, and its text
  std::string hash;        // FNV-1a 64 of the text and the tables' names, columns and numbers, hex
  TimeSpec time;
  std::vector<DataSpec> data;
  std::vector<VarSpec> vars;
  std::vector<ConstraintSpec> constraints;
  OutputSpec output;
  NetworkSpec network;
  OnlineSpec online;

  const VarSpec* var(const std::string& name) const;
  const DataSpec* table(const std::string& name) const;
  // The first deriv constraint x' = v on the tube x, or null.
  const ConstraintSpec* deriv_of(const std::string& x) const;
};

const char* kind_name(VarKind k);
const char* kind_name(ConstraintKind k);
// "fifo" or "priority", as written in [network] scheduling.
const char* scheduling_name(Scheduling s);

}  // namespace sillage
