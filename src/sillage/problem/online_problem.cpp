#include "sillage/problem/online_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/dynamics/ctc_second_deriv.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/problem/build_network.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/problem/var_refs.h"
#include "sillage/tube/tube.h"

namespace sillage {

using detail::csv_cell;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

ProblemError not_online(const SourcePos& pos, const std::string& found, const std::string& why) {
  return ProblemError(pos, found + " (" + why + ")", "what runs online (docs/online.md, \"From a problem file\")");
}

Interval error_of(const std::string& text, const SourcePos& pos) {
  const Interval e = text.empty() ? Interval(0) : Function({"t"}, text).eval(IntervalVector{Interval(0)});
  if (e.is_empty() || e.lb() < 0) throw ProblemError(pos, "the error " + text, "an error >= 0");
  return e;
}

// A tube's bound, "(e1, e2, ...)" of t ("" components free), or none when no component is bounded.
std::optional<Function> bound_of(const VarSpec& v) {
  bool any = false;
  std::string text = v.dim > 1 ? "(" : "";
  for (std::size_t i = 0; i < v.dim; ++i) {
    const std::string& e = v.value[i].expr;
    any = any || !e.empty();
    text += (i ? ", " : "") + (e.empty() ? std::string("[-oo, oo]") : e);
  }
  if (!any) return std::nullopt;
  return Function({"t"}, v.dim > 1 ? text + ")" : text);
}

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

}  // namespace

OnlineOptions online_options(const Problem& p) {
  OnlineOptions o;
  o.window = p.online.window.value_or(kInf);
  o.forget_every = p.online.forget_every;
  if (p.network.ratio) o.ratio = *p.network.ratio;
  return o;
}

struct OnlineProblem::Impl {
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

  explicit Impl(const Problem& problem) : p(problem) {}

  void declare_vars() {
    for (const VarSpec& v : p.vars) {
      if (!v.is_tube()) throw not_online(v.pos, std::string(kind_name(v.kind)) + " " + v.name, "a constant of the whole run");
      if (v.gates) throw not_online(v.pos, v.name + " gates = {data = ...}", "a value per time point from a table");
      IntervalVector x0(v.dim);
      for (const GateSpec& g : v.at) {
        IntervalVector z(v.dim);
        for (std::size_t i = 0; i < v.dim; ++i) z[i] = g.value[i].expr.empty() ? Interval() : error_free(g.value[i]);
        if (g.t_hi <= p.time.t0) x0 &= z;  // at t0, or before: the domain's start
        else waiting.push_back({Interval(std::max(g.t_lo, p.time.t0), g.t_hi), {v.name}, in_box(z)});
      }
      if (v.slices) {
        if (!clock.empty() && clock != v.slices->data)
          throw not_online(v.pos, v.name + " slices from " + v.slices->data,
                           "the periods come from one table, here " + clock);
        clock = v.slices->data;
        inputs.push_back(&v);
        est->add_input(v.name, v.dim);
      } else if (const auto bound = bound_of(v)) {
        est->add_bounded(v.name, *bound, x0);
      } else {
        est->add_state(v.name, v.dim, x0);
      }
    }
    outputs = p.online.outputs;
    if (outputs.empty()) {  // what [output] draws, else every tube
      const auto add = [&](const std::string& n) {
        if (std::find(outputs.begin(), outputs.end(), n) == outputs.end()) outputs.push_back(n);
      };
      for (const auto& [name, ij] : p.output.maps) add(name);
      for (const auto& [name, i] : p.output.plot_tubes) add(name);
      if (outputs.empty())
        for (const VarSpec& v : p.vars) add(v.name);
    }
  }
  static Interval error_free(const BoundSpec& b) { return Function({"t"}, b.expr).eval(IntervalVector{Interval(0)}); }
  // z ∈ box: a state's value stated at a time.
  static std::shared_ptr<const Ctc> in_box(const IntervalVector& z) {
    std::vector<std::string> names;
    std::string text = z.size() > 1 ? "(" : "";
    for (std::size_t i = 0; i < z.size(); ++i) {
      names.push_back("z" + std::to_string(i));
      text += (i ? ", " : "") + names.back();
    }
    return std::make_shared<CtcFunction>(Function(names, z.size() > 1 ? text + ")" : text), z);
  }
  std::string ref_name(const detail::VarRef& r, const SourcePos& pos) const {
    const VarSpec* v = p.var(r.var);
    if (!v || !v->is_tube()) throw not_online(pos, r.var, "not a tube variable");
    return v->kind == VarKind::Tube ? v->name : v->name + "[" + std::to_string(r.component) + "]";
  }
  void parse_inputs() {
    if (inputs.empty()) return;
    std::vector<std::string> names = p.table(clock)->table.columns();
    names.push_back("dt");
    for (const VarSpec* v : inputs) {
      input_values.emplace_back(names, v->slices->value.expr);
      input_bounds.push_back(bound_of(*v));
      for (const std::size_t c : detail::read_vars(input_values.back()))
        if (c + 1 < names.size()) needed[clock].insert(names[c]);
    }
  }
  void declare_constraints() {
    const auto dims = [&](const std::string& n) -> std::optional<std::size_t> {
      const VarSpec* v = p.var(n);
      return v ? std::optional<std::size_t>(v->dim) : std::nullopt;
    };
    const auto vec = [&](const std::string& n) {
      const VarSpec* v = p.var(n);
      return v && (v->kind == VarKind::TubeVector || v->kind == VarKind::Box);
    };
    std::set<std::string> with_deriv;
    for (const std::size_t ci : constraint_order(p)) {
      const ConstraintSpec& c = p.constraints[ci];
      switch (c.kind) {
        case ConstraintKind::Expr: {
          const detail::RewrittenExpr r = detail::rewrite_refs(c.expr, c.expr_pos, dims, vec, "");
          std::vector<std::string> names;
          for (const detail::VarRef& ref : r.refs) names.push_back(ref_name(ref, c.expr_pos));
          est->add(std::make_shared<CtcFunction>(Function(r.ids(), r.text)), names);
          break;
        }
        case ConstraintKind::Deriv:
          est->add_deriv(c.x, c.v);
          with_deriv.insert(c.x);
          break;
        case ConstraintKind::Increment:
          est->add(std::make_shared<CtcIncrement>(), {c.x, c.v});
          break;
        case ConstraintKind::SecondDeriv:
          est->add(std::make_shared<CtcSecondDeriv>(), {c.x, c.v});
          break;
        case ConstraintKind::Heading:
          est->add(std::make_shared<CtcHeading>(error_of(c.track, c.pos).ub()), {c.p, c.psi, c.dist, c.omega});
          break;
        case ConstraintKind::HeadingWindow: {
          const double width = p.time.points.empty()
                                   ? *p.time.delta
                                   : (p.time.points.back() - p.time.points.front()) /
                                         static_cast<double>(p.time.points.size() - 1);
          const std::size_t stride =
              c.stride ? c.stride : static_cast<std::size_t>(std::max(1.0, std::round(c.window / 4 / width)));
          const double accel = c.turn_accel.empty() ? kInf : error_of(c.turn_accel, c.pos).ub();
          est->add(std::make_shared<CtcHeadingWindow>(c.window, error_of(c.track, c.pos).ub(), accel, stride),
                   {c.p, c.psi, c.dist, c.dpsi, c.omega});
          break;
        }
        case ConstraintKind::PImpliesZ:
          throw not_online(c.pos, c.label, "the temporal SLAM's loops need the whole path");
        case ConstraintKind::Eval:
          plan_eval(c, with_deriv);
          break;
      }
    }
    for (const Waiting& w : waiting)
      if (!with_deriv.count(w.states[0]) && !implied_deriv(w.states[0]))
        throw not_online(p.var(w.states[0])->pos, w.states[0] + " at t = " + number_text(w.t.ub()),
                         "a value at a time after t0 needs the variable's derivative (a deriv constraint)");
  }
  bool implied_deriv(const std::string& y) const {
    for (const ConstraintSpec& c : p.constraints)
      if (c.kind == ConstraintKind::Eval)
        for (std::size_t j = 0; j < c.ys.size(); ++j)
          if (c.ys[j] == y && !c.vs[j].empty()) return true;
    return false;
  }
  void plan_eval(const ConstraintSpec& c, std::set<std::string>& with_deriv) {
    EvalPlan e;
    e.c = &c;
    for (std::size_t j = 0; j < c.ys.size(); ++j) {
      if (with_deriv.count(c.ys[j])) continue;
      if (c.vs[j].empty() && !p.deriv_of(c.ys[j]))
        throw not_online(c.pos, c.label, c.ys[j] + " has no derivative: online, an observation's time moves along y' = v");
      est->add_deriv(c.ys[j], c.vs[j].empty() ? p.deriv_of(c.ys[j])->v : c.vs[j]);
      with_deriv.insert(c.ys[j]);
    }
    const detail::RewrittenExpr r = detail::eval_observation(p, c);
    std::vector<std::size_t> offset;
    for (const std::string& y : c.ys) {
      offset.push_back(e.nz);
      e.nz += p.var(y)->dim;
    }
    const CsvTable& table = p.table(c.data)->table;
    const CsvTable* joined = c.join_data.empty() ? nullptr : &p.table(c.join_data)->table;
    std::vector<int> slots;
    for (const detail::VarRef& ref : r.refs) {
      const auto y = std::find(c.ys.begin(), c.ys.end(), ref.var);
      if (y != c.ys.end()) {
        slots.push_back(static_cast<int>(offset[static_cast<std::size_t>(y - c.ys.begin())] + ref.component));
      } else if (table.has_column(ref.var) || (joined && joined->has_column(ref.var))) {
        slots.push_back(-1);
        e.measured.push_back(ref.var);
      } else {
        throw not_online(c.expr_pos, ref.var + " in the observation", "online, an observation reads its own tubes and columns");
      }
    }
    std::set<std::string>& cols = needed[c.data];
    for (const std::string& col : e.measured)
      if (table.has_column(col)) cols.insert(col);
    cols.insert(c.time_columns.begin(), c.time_columns.end());
    for (const auto& [col, value] : c.where) cols.insert(col);
    if (joined) cols.insert(c.join_on);
    e.slots = std::make_shared<const std::vector<int>>(std::move(slots));
    e.obs = std::make_shared<CtcFunction>(Function(r.ids(), r.text));
    e.terr = error_of(c.time_error, c.pos);
    for (const auto& [col, text] : c.errors) e.errors[col] = error_of(text, c.pos);
    if (joined)
      for (std::size_t row = 0; row < joined->nb_rows(); ++row) e.join_rows.emplace(joined->row(row)[joined->column(c.join_on)], row);
    evals[c.data].push_back(std::move(e));
  }

  // The row's values in its table's column order (NaN where not given);
  // every column the constraints read given, no unknown one, none NaN.
  std::vector<double> values_of(const StreamRow& row) const {
    const CsvTable& table = p.table(row.table)->table;
    for (const auto& [name, value] : row.columns) {
      if (!table.has_column(name)) throw Error("a row of " + row.table + ": no column " + name + " in that table");
      if (std::isnan(value)) throw Error("a row of " + row.table + ": " + name + " is NaN");
    }
    std::vector<double> values(table.columns().size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < values.size(); ++i)
      if (const auto it = row.columns.find(table.columns()[i]); it != row.columns.end()) values[i] = it->second;
    if (const auto it = needed.find(row.table); it != needed.end())
      for (const std::string& col : it->second)
        if (!row.columns.count(col)) throw Error("a row of " + row.table + " without its column " + col);
    return values;
  }

  // Time advances to t with the clock row's inputs (none for a tick).
  void advance(double t, const std::vector<std::pair<std::string, IntervalVector>>& given) {
    est->advance(t, given);
    release();
    report();
  }
  // The estimate to the callback, when it changed since the last report.
  void report() {
    const std::size_t n = est->stats().updates;
    if (n == reported) return;
    reported = n;
    if (updated) updated();
  }
  // The waiting observations whose time has begun.
  void release() {
    std::vector<Waiting> still;
    for (Waiting& w : waiting) {
      if (w.t.lb() <= est->now()) est->observe(w.t, w.states, std::move(w.ctc));
      else still.push_back(std::move(w));
    }
    waiting = std::move(still);
  }
  // δ: to the first grid point at or after t.
  void tick(double t) {
    if (delta == 0) {
      throw Error("time advances with the rows of " + (clock.empty() ? p.time.points_data : clock) +
                  " (the [time] points), not by a row of no table");
    }
    while (est->now() < t) {
      ++ticks;
      advance(p.time.t0 + static_cast<double>(ticks) * delta, {});
    }
  }
  void clock_row(const StreamRow& row, const std::vector<double>& values) {
    if (!row.t) throw Error("a row of " + row.table + " without \"t\", the end of its period");
    const double t = *row.t;
    if (!(t > est->now())) throw Error("a row of " + row.table + " at t = " + number_text(t) + ", not after now = " + number_text(est->now()));
    std::vector<std::pair<std::string, IntervalVector>> given;
    IntervalVector args(values.size() + 1);
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isnan(values[i])) args[i] = csv_cell(values[i]);  // a column not given is not read
    const Interval period(est->now(), t);
    args[values.size()] = Interval(t) - Interval(est->now());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const VarSpec* v = inputs[i];
      Interval x = input_values[i].eval(args);
      if (input_bounds[i]) x &= detail::unknown_where_undefined(input_bounds[i]->eval(IntervalVector{period}));
      if (x.is_empty()) throw Error("a row of " + row.table + " gives " + v->name + " an empty value over [" +
                                    number_text(period.lb()) + ", " + number_text(t) + "]");
      given.emplace_back(v->name, IntervalVector{x});
    }
    advance(t, given);
  }
  void observation_rows(const StreamRow& row, const std::vector<double>& values) {
    const CsvTable& table = p.table(row.table)->table;
    std::vector<Waiting> obs;
    const double arrived = row.t.value_or(est->now());
    for (const EvalPlan& e : evals.at(row.table)) {
      const ConstraintSpec& c = *e.c;
      if (!detail::eval_row_kept(c, table, values)) continue;
      std::span<const double> join_values;
      const CsvTable* joined = c.join_data.empty() ? nullptr : &p.table(c.join_data)->table;
      if (joined) {
        const auto j = e.join_rows.find(values[table.column(c.join_on)]);
        if (j == e.join_rows.end())
          throw Error("a row of " + row.table + ": " + c.join_on + " = " + detail::cell_text(values[table.column(c.join_on)]) +
                      " is in no row of " + c.join_data);
        join_values = joined->row(j->second);
      }
      const Interval t = c.time_columns.empty()
                             ? Interval(est->window_start(), std::min(arrived, est->now()))
                             : detail::eval_row_time(c, table, values, e.terr, Interval(-kInf, kInf));
      if (t.lb() < est->window_start())
        throw Error("a row of " + row.table + " at t in " + t.str() + ": older than the window [" +
                    number_text(est->window_start()) + ", " + number_text(est->now()) + "]");
      if (t.lb() > est->now() + p.online.lead)
        throw Error("a row of " + row.table + " at t in " + t.str() + ": beyond now = " + number_text(est->now()) +
                    " + lead " + number_text(p.online.lead) + " s ([online] lead)");
      std::vector<Interval> measured;
      for (const std::string& col : e.measured) {
        const auto err = e.errors.find(col);
        const double v = table.has_column(col) ? values[table.column(col)] : join_values[joined->column(col)];
        measured.push_back(csv_cell(v) + Interval(-1, 1) * (err == e.errors.end() ? Interval(0) : err->second));
      }
      obs.push_back({t, c.ys, std::make_shared<detail::RowObservation>(e.obs, e.slots, e.nz, IntervalVector(measured))});
    }
    for (Waiting& w : obs) waiting.push_back(std::move(w));
    release();
  }
};

OnlineProblem::OnlineProblem(const Problem& p, std::optional<OnlineOptions> options) : impl_(std::make_unique<Impl>(p)) {
  Impl& m = *impl_;
  m.est = std::make_unique<OnlineEstimator>(p.time.t0, options.value_or(online_options(p)));
  m.est->network().set_scheduling(p.network.scheduling);
  if (p.time.points.empty()) m.delta = *p.time.delta;
  m.declare_vars();
  m.parse_inputs();
  m.declare_constraints();
  if (m.clock.empty() && m.delta == 0) m.clock = p.time.points_data;
}

OnlineProblem::~OnlineProblem() = default;

void OnlineProblem::feed(const StreamRow& row) {
  Impl& m = *impl_;
  if (row.t && !std::isfinite(*row.t)) throw Error("a row at t = " + number_text(*row.t) + ": not finite");
  if (row.table.empty()) {
    if (!row.t) throw Error("a row of no table (a tick) without \"t\"");
    m.tick(*row.t);
    return;
  }
  if (!m.p.table(row.table)) throw Error("no table " + row.table + " in " + m.p.file);
  const bool is_clock = row.table == m.clock, observed = m.evals.count(row.table) > 0;
  if (!is_clock && !observed)
    throw Error("the table " + row.table + " is read by no online constraint (the clock is " +
                (m.clock.empty() ? "a slice width" : m.clock) + ")");
  const std::vector<double> values = m.values_of(row);
  if (is_clock) {
    m.clock_row(row, values);
  } else if (row.t && m.delta > 0) {
    m.tick(*row.t);
  }
  if (observed) m.observation_rows(row, values);
  m.report();
}

void OnlineProblem::on_update(std::function<void()> f) { impl_->updated = std::move(f); }

const std::vector<std::string>& OnlineProblem::outputs() const { return impl_->outputs; }

std::size_t OnlineProblem::waiting() const { return impl_->waiting.size(); }

OnlineEstimator& OnlineProblem::estimator() { return *impl_->est; }

const OnlineEstimator& OnlineProblem::estimator() const { return *impl_->est; }

std::vector<StreamRow> OnlineProblem::recorded_rows() const {
  const Impl& m = *impl_;
  struct Keyed {
    double key;
    int rank;  // clock rows before the observations of their time
    StreamRow row;
  };
  std::vector<Keyed> rows;
  const auto row_of = [&](const std::string& name, std::size_t i) {
    const CsvTable& t = m.p.table(name)->table;
    StreamRow r{name, std::nullopt, {}};
    const std::span<const double> v = t.row(i);
    for (std::size_t c = 0; c < v.size(); ++c) r.columns[t.columns()[c]] = v[c];
    return r;
  };
  const std::vector<double>& pts = m.p.time.points;
  if (m.delta > 0) {
    const auto n = static_cast<std::size_t>(std::ceil((m.p.time.tf - m.p.time.t0) / m.delta));
    for (std::size_t k = 1; k <= n; ++k) {
      const double t = m.p.time.t0 + static_cast<double>(k) * m.delta;
      rows.push_back({t, 0, StreamRow{"", t, {}}});
    }
  } else {
    const CsvTable& clock = m.p.table(m.clock)->table;
    const bool periods = !m.inputs.empty();  // row k: the period [t_k, t_k+1]
    for (std::size_t k = periods ? 0 : 1; k + 1 < pts.size() + (periods ? 0 : 1) && k < clock.nb_rows(); ++k) {
      StreamRow r = row_of(m.clock, k);
      r.t = periods ? pts[k + 1] : pts[k];
      rows.push_back({*r.t, 0, std::move(r)});
    }
  }
  for (const auto& [name, plans] : m.evals) {
    if (name == m.clock) continue;
    const CsvTable& t = m.p.table(name)->table;
    for (std::size_t i = 0; i < t.nb_rows(); ++i) {
      double stamp = kInf;  // no time column: after the whole run
      for (const EvalPlan& e : plans) {
        if (e.c->time_columns.empty()) continue;
        double s = -kInf;
        for (const std::string& col : e.c->time_columns) s = std::max(s, t.row(i)[t.column(col)]);
        stamp = std::min(stamp, s);
      }
      StreamRow r = row_of(name, i);
      if (std::isfinite(stamp)) r.t = std::max(stamp, m.p.time.t0);
      rows.push_back({stamp, 1, std::move(r)});
    }
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Keyed& a, const Keyed& b) {
    return a.key < b.key || (a.key == b.key && a.rank < b.rank);
  });
  // An observation goes after the clock row that reaches its stamp.
  std::vector<StreamRow> out;
  std::vector<StreamRow> held;
  double reached = m.p.time.t0;
  for (Keyed& k : rows) {
    if (k.rank == 0) {
      out.push_back(std::move(k.row));
      reached = k.key;
      for (StreamRow& h : held) out.push_back(std::move(h));
      held.clear();
    } else if (k.key <= reached) {
      out.push_back(std::move(k.row));
    } else {
      held.push_back(std::move(k.row));
    }
  }
  for (StreamRow& h : held) out.push_back(std::move(h));
  return out;
}

}  // namespace sillage
