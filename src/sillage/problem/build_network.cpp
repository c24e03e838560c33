#include "sillage/problem/build_network.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <optional>
#include <span>
#include <unordered_set>

#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_deriv_angle.h"
#include "sillage/dynamics/ctc_eval_angle.h"
#include "sillage/problem/angle_terms.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_eval_list.h"
#include "sillage/dynamics/ctc_qeval.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/dynamics/ctc_second_deriv.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/expr/tape.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/problem/python_constraint.h"
#include "sillage/problem/var_refs.h"
#include "sillage/slam/ctc_p_implies_z.h"
#include "sillage/tube/tube.h"

namespace sillage {

using detail::RewrittenExpr;
using detail::VarRef;
using detail::rewrite_refs;
using detail::equation_ctc;
using detail::eval_row_kept;
using detail::eval_row_time;
using detail::RowObservation;
using detail::csv_cell;
using detail::cell_text;
using detail::read_vars;

namespace {

Interval constant(const BoundSpec& b) {
  if (b.expr.empty()) return Interval();
  return Function({"t"}, b.expr).eval(IntervalVector{Interval(0)});
}

Interval constant_text(const std::string& text, const SourcePos& pos) {
  const Interval x = constant(BoundSpec{text, pos});
  if (x.is_empty() || x.lb() < 0) throw ProblemError(pos, "the error " + text, "an error >= 0");
  return x;
}

// The observation when it only says "each evaluated value is a column"
// ("y - z", "(h - tau, y - z)"): per tube of c.ys its column, so z_i is the
// column's interval itself, as a hand-written network does (no CtcFunction,
// and CtcEval starts from the measurement). None for any other expression.
std::optional<std::vector<std::string>> direct_columns(const ConstraintSpec& c, const CsvTable& table,
                                                       const std::vector<const VarDomain*>& ys) {
  std::string e;
  for (char ch : c.expr)
    if (!std::isspace(static_cast<unsigned char>(ch))) e += ch;
  if (ys.size() > 1) {
    if (e.size() < 2 || e.front() != '(' || e.back() != ')') return std::nullopt;
    e = e.substr(1, e.size() - 2);
  }
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t comma = e.find(',', start);
    parts.push_back(e.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() != ys.size()) return std::nullopt;
  std::vector<std::string> cols(ys.size());
  for (std::size_t j = 0; j < ys.size(); ++j) {
    const std::size_t minus = parts[j].find('-');
    if (minus == std::string::npos || ys[j]->spec->kind != VarKind::Tube) return std::nullopt;
    const std::string y = parts[j].substr(0, minus), col = parts[j].substr(minus + 1);
    if (y != c.ys[j] || !table.has_column(col)) return std::nullopt;
    cols[j] = col;
  }
  return cols;
}

// The slices of x from a table (row k: slice k of [time] points), after the
// time points added since (gates of 'at', of evals) split some of them.
// Gate k: the hull of the slices around it (a value per period, not a
// continuous trajectory: it may jump at the stamps). Written in place: a
// row is evaluated once for all the slices it covers.
void set_slices(Tube& x, const Problem& p, const SliceDataSpec& s) {
  const CsvTable& table = p.table(s.data)->table;
  std::vector<std::string> names = table.columns();
  names.push_back("dt");
  const Function f(names, s.value.expr);
  const std::vector<double>& pts = p.time.points;
  const TDomain& td = *x.tdomain();
  IntervalVector args(names.size());
  const std::vector<std::size_t> read = read_vars(f);
  for (std::size_t c : read)
    if (c < table.columns().size()) table.check_numeric(c);  // the loader checked them; a row holds NaN in text
  Tube::Writer w = x.write();
  const std::span<Interval> slices = w.slices();
  std::size_t row = 0, evaluated = table.nb_rows();
  Interval value;
  for (std::size_t k = 0; k < slices.size(); ++k) {
    while (row + 1 < table.nb_rows() && pts[row + 1] <= td.t(k)) ++row;
    if (row != evaluated) {
      const std::span<const double> values = table.row(row);
      for (std::size_t c : read)
        if (c < values.size()) args[c] = csv_cell(values[c]);  // the last variable, dt, is set below
      args[values.size()] = Interval(pts[row + 1]) - Interval(pts[row]);  // the row's slice, outward
      value = f.eval(args);
      evaluated = row;
    }
    slices[k] &= value;
  }
  const std::span<Interval> gates = w.gates();
  const std::size_t n = slices.size();
  for (std::size_t k = 0; k <= n; ++k) gates[k] = (k > 0 ? slices[k - 1] : slices[k]) | (k < n ? slices[k] : slices[k - 1]);
}

// The value at each stamp of the table (gates = {data, value}), from its
// row: a fix at the stamp as written, a decimal that the time point (its
// nearest double) need not be (time_fixes).
void table_gate_fixes(std::vector<TubeObservation>& fixes, const Problem& p, const SliceDataSpec& g,
                      const Interval& domain) {
  const CsvTable& table = p.table(g.data)->table;
  const Function f(table.columns(), g.value.expr);
  IntervalVector args(table.columns().size());
  const std::vector<std::size_t> read = read_vars(f);
  for (std::size_t c : read) table.check_numeric(c);  // the loader checked them; a row holds NaN in text
  for (std::size_t row = 0; row < table.nb_rows(); ++row) {  // row k: time point k (the loader checked the count)
    const std::span<const double> values = table.row(row);
    for (std::size_t c : read) args[c] = csv_cell(values[c]);
    fixes.push_back({csv_cell(p.time.points[row]) & domain,
                     IntervalVector{f.eval(args)}, nullptr, g.data + " line " + std::to_string(table.line(row))});
  }
}

// Whether the expression names the variable t (an identifier token).
bool names_t(const std::string& e) {
  const auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t i = 0; i < e.size(); ++i)
    if (e[i] == 't' && (i == 0 || !ident(e[i - 1])) && (i + 1 == e.size() || !ident(e[i + 1]))) return true;
  return false;
}

// A bound without t, or nothing: one interval for every slice and gate.
std::optional<Interval> constant_bound(const BoundSpec& b) {
  if (b.expr.empty()) return Interval();
  if (names_t(b.expr)) return std::nullopt;
  try {
    return detail::unknown_where_undefined(Function(std::vector<std::string>{}, b.expr).eval(IntervalVector(0)));
  } catch (const ParseError&) {
    return std::nullopt;  // Function({"t"}, ...) says what is wrong
  }
}

// A constant bound is evaluated once, not at each of the slices and gates
// (the same values as Tube(td, f)).
Tube tube_of(const std::shared_ptr<TDomain>& td, const BoundSpec& b) {
  if (const std::optional<Interval> c = constant_bound(b)) return Tube(td, *c);
  return Tube(td, Function({"t"}, b.expr));
}

}  // namespace

DomainRef VarDomain::whole() const {
  return spec->kind == VarKind::Tube ? DomainRef(tubes->shared_component(0)) : DomainRef(tubes);
}

DomainRef VarDomain::component(std::size_t i) const {
  if (tubes) return spec->kind == VarKind::Tube ? DomainRef(tubes->shared_component(0)) : DomainRef::component(tubes, i);
  if (interval) return DomainRef(interval);
  return DomainRef::component(box, i);
}

std::size_t VarDomain::memory_bytes() const {
  if (tubes) {
    std::size_t s = 0;
    for (std::size_t i = 0; i < tubes->size(); ++i) s += (*tubes)[i].memory_bytes();
    return s;
  }
  return sizeof(Interval) * (box ? box->size() : 1);
}

const VarDomain& BuiltProblem::var(const std::string& name) const {
  for (const VarDomain& v : vars)
    if (v.spec->name == name) return v;
  throw Error("no variable '" + name + "'");
}

std::size_t BuiltProblem::constraint_of_node(std::size_t n) const {
  std::size_t c = order.empty() ? 0 : order[0];  // the last one, in add order, to start at or before n
  for (const std::size_t i : order)
    if (first_node[i] <= n) c = i;
  return c;
}

std::vector<std::size_t> constraint_order(const Problem& p) {
  std::vector<std::size_t> order(p.constraints.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (p.network.order == ConstraintOrder::Cost) {
    const auto rank = [&](std::size_t i) {
      switch (p.constraints[i].kind) {
        case ConstraintKind::Eval: return 0;
        case ConstraintKind::Expr: return 1;
        case ConstraintKind::Increment: return 2;
        case ConstraintKind::Heading: return 3;
        case ConstraintKind::Deriv:
        case ConstraintKind::SecondDeriv: return 4;
        case ConstraintKind::HeadingWindow: return 5;
        case ConstraintKind::PImpliesZ: return 6;  // a t-plane per run: the dearest
        case ConstraintKind::Python: return 5;     // the interpreter, whole tubes per run
      }
      return 6;
    };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
  }
  return order;
}

std::size_t BuiltProblem::memory_bytes() const {
  std::size_t s = 0;
  for (const VarDomain& v : vars) s += v.memory_bytes();
  return s;
}

std::size_t nb_slices_for(const Problem& p, double delta) {
  if (!p.time.points.empty()) return p.time.points.size() - 1;
  return static_cast<std::size_t>(std::ceil((p.time.tf - p.time.t0) / delta));
}

std::size_t peak_memory_estimate(const Problem& p, std::size_t slices) {
  std::size_t bytes = std::size_t{8} << 20;  // the program and its libraries (8.5 MB for a problem of 100 slices)
  for (const VarSpec& v : p.vars) bytes += v.is_tube() ? v.dim * (slices + 1) * 150 : v.dim * 16;
  for (const ConstraintSpec& c : p.constraints)
    if (c.kind == ConstraintKind::Eval) bytes += 200 * p.table(c.data)->table.nb_rows();
  return bytes;
}

void check_memory(const Problem& p, std::size_t slices, const std::string& what) {
  const double need = static_cast<double>(peak_memory_estimate(p, slices));
  const double have = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  if (have > 0 && need > have) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s gives %zu slices: about %.1f GiB of memory at the peak of the solve, more "
                  "than this machine's %.1f GiB; a larger slice width (or fewer tubes)",
                  what.c_str(), slices, need / 1073741824.0, have / 1073741824.0);
    throw Error(buf);
  }
}

namespace {

BuiltProblem build_on(const Problem& p, std::shared_ptr<TDomain> td);

}  // namespace

BuiltProblem build_network(const Problem& p, double delta) {
  return build_on(p, p.time.points.empty() ? TDomain::create(p.time.t0, p.time.tf, delta) : TDomain::create(p.time.points));
}

BuiltProblem build_network(const Problem& p, const std::vector<double>& points) {
  if (points.size() < 2 || points.front() != p.time.t0 || points.back() != p.time.tf)
    throw Error("build_network: time points from t0 to tf expected");
  return build_on(p, TDomain::create(points));
}

namespace {

// The values of v stated at times that are not time points (time_fixes): one
// CtcEvalList on v and its derivative, the first deriv constraint's on v, or
// the whole line (none: a value at a time between two doubles then bounds no
// gate, only the slices around it).
void add_time_fixes(BuiltProblem& b, const Problem& p, const VarDomain& v, std::vector<TubeObservation> fixes) {
  const ConstraintSpec* d = p.deriv_of(v.spec->name);
  VarDomain w;  // the derivative, or the whole line
  if (d) {
    w = b.var(d->v);
  } else {
    w.spec = v.spec;
    w.tubes = std::make_shared<TubeVector>(std::vector<Tube>(v.spec->dim, Tube(b.td, Interval())));
  }
  b.value_nodes.push_back("the values of " + v.spec->name + " at times between two doubles (" +
                          (v.spec->at.empty() ? v.spec->pos.str() : v.spec->at[0].pos.str()) + ")");
  b.cn->add(std::make_shared<CtcEvalList>(std::move(fixes)), {v.whole(), w.whole()});
}

BuiltProblem build_on(const Problem& p, std::shared_ptr<TDomain> td) {
  BuiltProblem b;
  b.td = std::move(td);
  for (const VarSpec& v : p.vars)
    for (const GateSpec& g : v.at)
      if (g.t_lo == g.t_hi && g.t > p.time.t0 && g.t < p.time.tf) b.td->sample(g.t);
  for (const ConstraintSpec& c : p.constraints) {
    if (c.kind != ConstraintKind::Eval || !c.gates) continue;
    const CsvTable& table = p.table(c.data)->table;
    const Interval terr = constant_text(c.time_error, c.pos);
    for (std::size_t row = 0; row < table.nb_rows(); ++row) {
      if (!eval_row_kept(c, table, table.row(row))) continue;
      const Interval t = eval_row_time(c, table, table.row(row), terr, b.td->t0_tf());
      if (t.is_empty()) continue;
      for (const double s : {t.lb(), t.ub()})
        if (s > p.time.t0 && s < p.time.tf) b.td->sample(s);
    }
  }
  b.cn = std::make_unique<ContractorNetwork>();
  ContractorNetwork& cn = *b.cn;
  if (p.network.ratio) cn.set_ratio(*p.network.ratio);
  cn.set_scheduling(p.network.scheduling);
  std::vector<std::vector<TubeObservation>> time_fixes(p.vars.size());  // per variable
  for (const VarSpec& v : p.vars) {
    VarDomain d;
    d.spec = std::make_shared<const VarSpec>(v);
    if (v.is_tube()) {
      std::vector<Tube> comps;
      for (const BoundSpec& bs : v.value) comps.push_back(tube_of(b.td, bs));
      if (v.angle) comps[0].set_angle(true);
      if (v.slices) set_slices(comps[0], p, *v.slices);
      if (v.gates) table_gate_fixes(time_fixes[b.vars.size()], p, *v.gates, b.td->t0_tf());
      d.tubes = std::make_shared<TubeVector>(std::move(comps));
      for (const GateSpec& g : v.at) {
        IntervalVector z(v.dim);
        for (std::size_t i = 0; i < v.dim; ++i) z[i] = constant(g.value[i]);
        if (g.t_lo != g.t_hi) {  // a decimal between two doubles: a fix at its time
          time_fixes[b.vars.size()].push_back({Interval(g.t_lo, g.t_hi) & b.td->t0_tf(), z, nullptr,
                                               v.name + " at t = " + cell_text(g.t) + " (" + g.pos.str() + ")"});
          continue;
        }
        const std::size_t k = static_cast<std::size_t>(b.td->time_index(g.t));
        for (std::size_t i = 0; i < v.dim; ++i) {
          Tube& x = (*d.tubes)[i];
          x.set_gate(k, x.gate(k) & z[i]);
        }
      }
    } else if (v.kind == VarKind::Interval) {
      d.interval = std::make_shared<Interval>(constant(v.value[0]));
    } else {
      IntervalVector x(v.dim);
      for (std::size_t i = 0; i < v.dim; ++i) x[i] = constant(v.value[i]);
      d.box = std::make_shared<IntervalVector>(x);
    }
    b.vars.push_back(std::move(d));
  }

  auto dims = [&](const std::string& n) -> std::optional<std::size_t> {
    const VarSpec* v = p.var(n);
    return v ? std::optional<std::size_t>(v->dim) : std::nullopt;
  };
  auto vec = [&](const std::string& n) {
    const VarSpec* v = p.var(n);
    return v && (v->kind == VarKind::TubeVector || v->kind == VarKind::Box);
  };
  const std::set<std::string> angles = detail::angle_names(p);
  b.first_node.assign(p.constraints.size(), 0);
  b.order = constraint_order(p);
  for (const std::size_t ci : b.order) {
    const ConstraintSpec& c = p.constraints[ci];
    b.first_node[ci] = cn.nb_ctc();
    switch (c.kind) {
      case ConstraintKind::Expr: {
        const RewrittenExpr r = rewrite_refs(c.expr, c.expr_pos, dims, vec, "");
        std::vector<std::size_t> order;
        const auto ctc = equation_ctc(r, angles, c.expr_pos, c.label, order);
        std::vector<DomainRef> args;
        for (const std::size_t i : order) args.push_back(b.var(r.refs[i].var).component(r.refs[i].component));
        cn.add(ctc, args);
        break;
      }
      case ConstraintKind::Deriv:
      case ConstraintKind::SecondDeriv:
      case ConstraintKind::Increment: {
        const VarDomain &x = b.var(c.x), &v = b.var(c.v);
        std::shared_ptr<const NetworkCtc> ctc;
        if (c.kind == ConstraintKind::Deriv && angles.count(c.x)) ctc = std::make_shared<CtcDerivAngle>();
        else if (c.kind == ConstraintKind::Deriv) ctc = std::make_shared<CtcDeriv>();
        else if (c.kind == ConstraintKind::SecondDeriv) ctc = std::make_shared<CtcSecondDeriv>();
        else ctc = std::make_shared<CtcIncrement>();
        cn.add(ctc, {x.whole(), v.whole()});
        break;
      }
      case ConstraintKind::Heading: {
        const VarDomain& pos = b.var(c.p);
        const auto scalar = [&](const std::string& n) { return b.var(n).tubes->shared_component(0); };
        cn.add(std::make_shared<CtcHeading>(constant_text(c.track, c.pos).ub()),
               {pos.tubes, scalar(c.psi), scalar(c.dist), scalar(c.omega)});
        break;
      }
      case ConstraintKind::HeadingWindow: {
        const auto scalar = [&](const std::string& n) { return b.var(n).tubes->shared_component(0); };
        // A window every quarter of a window at the mean slice width, unless the file says.
        const double mean_width = (b.td->tf() - b.td->t0()) / static_cast<double>(b.td->nb_slices());
        const std::size_t stride =
            c.stride ? c.stride : static_cast<std::size_t>(std::max(1.0, std::round(c.window / 4 / mean_width)));
        const double accel = c.turn_accel.empty() ? INFINITY : constant_text(c.turn_accel, c.pos).ub();
        cn.add(std::make_shared<CtcHeadingWindow>(c.window, constant_text(c.track, c.pos).ub(), accel, stride),
               {b.var(c.p).tubes, scalar(c.psi), scalar(c.dist), scalar(c.dpsi), scalar(c.omega)});
        break;
      }
      case ConstraintKind::PImpliesZ:
        cn.add(std::make_shared<CtcPImpliesZ>(c.eps, c.fast), {b.var(c.p).tubes, b.var(c.w).tubes, b.var(c.z).tubes});
        break;
      case ConstraintKind::Python: {  // the user's sillage.TubeCtc, through the Python module's factory
        std::vector<const VarDomain*> args;
        std::vector<DomainRef> refs;
        for (const std::string& a : c.args) {
          args.push_back(&b.var(a));
          refs.push_back(b.var(a).whole());
        }
        cn.add(make_python_constraint(c, p.file, args), refs);
        break;
      }
      case ConstraintKind::Eval: {
        const DataSpec& data = *p.table(c.data);
        const CsvTable* joined = c.join_data.empty() ? nullptr : &p.table(c.join_data)->table;
        std::map<double, std::size_t> join_rows;  // value of join_on -> row of the joined table
        if (joined)
          for (std::size_t r = 0; r < joined->nb_rows(); ++r) join_rows.emplace(joined->row(r)[joined->column(c.join_on)], r);
        const auto has_column = [&](const std::string& n) { return data.table.has_column(n) || (joined && joined->has_column(n)); };
        std::vector<const VarDomain*> ys;
        for (const std::string& y : c.ys) ys.push_back(&b.var(y));
        const auto y_index = [&](const std::string& n) {
          for (std::size_t j = 0; j < c.ys.size(); ++j)
            if (c.ys[j] == n) return j;
          return c.ys.size();
        };
        // y' = v is stated with the eval: enforced over the whole tube when no
        // deriv constraint does it, so that the rows' fronts are left to it (each
        // CtcEval sweeping its own over the tube was quadratic in the rows).
        for (const std::size_t j : detail::implied_derivs(p, c)) {
          const DomainRef v = b.var(c.vs[j]).whole();
          if (angles.count(c.ys[j])) cn.add(std::make_shared<CtcDerivAngle>(), {ys[j]->whole(), v});
          else cn.add(std::make_shared<CtcDeriv>(), {ys[j]->whole(), v});
        }
        const RewrittenExpr r = detail::eval_observation(p, c);
        const Function f(r.ids(), r.text);
        const auto eval = std::make_shared<CtcEval>();
        const auto eval_angle = std::make_shared<CtcEvalAngle>();
        std::vector<std::size_t> obs_order;  // the refs in the order of the observation's box
        const auto row_obs = equation_ctc(r, angles, c.expr_pos, c.label, obs_order);
        const auto obs = std::make_shared<CtcFunction>(f);
        const Interval terr = constant_text(c.time_error, c.pos);
        std::map<std::string, Interval> errs;
        for (const auto& [col, text] : c.errors) errs[col] = constant_text(text, c.pos);
        std::span<const double> join_values;  // the joined row of the current row
        const auto measured = [&](std::span<const double> values, const std::string& col) {
          const auto it = errs.find(col);
          const Interval e = it == errs.end() ? Interval(0) : it->second;
          const double v = data.table.has_column(col) ? values[data.table.column(col)] : join_values[joined->column(col)];
          return csv_cell(v) + Interval(-1, 1) * e;
        };
        const auto direct = direct_columns(c, data.table, ys);
        // One CtcEvalList node for all the rows when each row's observation
        // involves only the evaluated tube and the row's values (ranges,
        // position fixes): no node, domain and name per row (plaza1's 3529
        // ranges were 7 058 nodes and 17 647 domains).
        const bool listed = detail::eval_rows_listed(p, c, r);
        if (c.q && !listed)
          throw ProblemError(c.pos, "q on " + c.label,
                             "q on an eval over one tube with its derivative whose observation reads only that tube "
                             "and the row's columns (its rows one CtcQEval)");
        const std::size_t nz = ys[0]->spec->kind == VarKind::Tube ? 1 : ys[0]->spec->dim;
        std::shared_ptr<const std::vector<int>> slots;  // per reference: its component of z, or -1 (a value)
        if (listed && !direct) {
          std::vector<int> s;
          for (const VarRef& ref : r.refs)
            s.push_back(y_index(ref.var) < ys.size() ? (nz == 1 ? 0 : static_cast<int>(ref.component)) : -1);
          slots = std::make_shared<const std::vector<int>>(std::move(s));
        }
        std::vector<TubeObservation> fixes;
        for (std::size_t row = 0; row < data.table.nb_rows(); ++row) {
          const std::span<const double> values = data.table.row(row);
          if (!eval_row_kept(c, data.table, values)) continue;
          if (joined) {
            const auto j = join_rows.find(values[data.table.column(c.join_on)]);
            if (j == join_rows.end()) detail::check_join_keys(c, data.table, *joined, c.pos);  // throws; the loader checked them
            join_values = joined->row(j->second);
          }
          const Interval row_t = eval_row_time(c, data.table, values, terr, b.td->t0_tf());
          if (row_t.is_empty()) continue;  // a measurement outside the time domain says nothing about it
          b.extra_domains += 1 + ys.size();
          if (listed) {
            TubeObservation o{row_t, IntervalVector(nz), nullptr, c.data + " line " + std::to_string(data.table.line(row))};
            if (direct) {
              o.z[0] = measured(values, (*direct)[0]);
            } else {
              std::vector<Interval> measured_values;
              for (std::size_t k = 0; k < r.refs.size(); ++k)
                if ((*slots)[k] < 0) measured_values.push_back(measured(values, r.refs[k].var));
              o.ctc = std::make_shared<RowObservation>(obs, slots, nz, IntervalVector(measured_values));
            }
            fixes.push_back(std::move(o));
            continue;
          }
          auto t = std::make_shared<Interval>(row_t);
          // The row's domains are named after its line, so that an emptiness names the measurement.
          const std::string row_name = c.data + " line " + std::to_string(data.table.line(row));
          const std::string of_row = " (" + row_name + ")";
          // One z per evaluated tube, all at the same time t.
          std::vector<std::shared_ptr<Interval>> z1(ys.size());
          std::vector<std::shared_ptr<IntervalVector>> zn(ys.size());
          for (std::size_t j = 0; j < ys.size(); ++j) {
            const VarDomain& y = *ys[j];
            if (y.spec->kind == VarKind::Tube) z1[j] = std::make_shared<Interval>(direct ? measured(values, (*direct)[j]) : Interval());
            else zn[j] = std::make_shared<IntervalVector>(y.spec->dim);
            std::vector<DomainRef> eval_args{t, z1[j] ? DomainRef(z1[j]) : DomainRef(zn[j]), y.whole()};
            if (!c.vs[j].empty()) eval_args.push_back(b.var(c.vs[j]).whole());
            if (angles.count(c.ys[j])) cn.add(std::static_pointer_cast<const NetworkCtc>(eval_angle), eval_args);
            else cn.add(std::static_pointer_cast<const NetworkCtc>(eval), eval_args);
            cn.set_ctc_name(cn.nb_ctc() - 1, row_name);  // it may empty y itself: the row is named then too
            cn.set_name(eval_args[1], y.spec->name + "(t)" + of_row);
          }
          cn.set_name(t, "t" + of_row);
          if (direct) continue;
          std::vector<DomainRef> args;
          for (const std::size_t i : obs_order) {
            const VarRef& ref = r.refs[i];
            const std::size_t j = y_index(ref.var);
            if (j < ys.size()) {
              args.push_back(z1[j] ? DomainRef(z1[j]) : DomainRef::component(zn[j], ref.component));
            } else if (has_column(ref.var)) {
              args.push_back(std::make_shared<Interval>(measured(values, ref.var)));
              cn.set_name(args.back(), ref.var + of_row);
              ++b.extra_domains;
            } else {
              args.push_back(b.var(ref.var).component(ref.component));
            }
          }
          cn.add(row_obs, args);
          cn.set_ctc_name(cn.nb_ctc() - 1, row_name);
        }
        if (!fixes.empty() && c.q) {  // outliers: a CtcQEval per group of rows
          std::vector<Interval> times;
          for (const TubeObservation& o : fixes) times.push_back(o.t);
          for (const std::vector<std::size_t>& g : detail::outlier_groups(c, times)) {
            std::vector<TubeObservation> group;
            for (const std::size_t i : g) group.push_back(fixes[i]);
            cn.add(std::make_shared<CtcQEval>(static_cast<int>(*c.q), std::move(group)),
                   {ys[0]->whole(), b.var(c.vs[0]).whole()});
          }
        } else if (!fixes.empty()) {
          cn.add(std::make_shared<CtcEvalList>(std::move(fixes)), {ys[0]->whole(), b.var(c.vs[0]).whole()});
        }
        break;
      }
    }
  }
  b.first_value_node = cn.nb_ctc();
  for (std::size_t i = 0; i < b.vars.size(); ++i)
    if (!time_fixes[i].empty()) add_time_fixes(b, p, b.vars[i], std::move(time_fixes[i]));
  for (const VarDomain& v : b.vars) {
    if (v.tubes) cn.set_name(v.whole(), v.spec->name);
    else if (v.interval) cn.set_name(v.interval, v.spec->name);
    else cn.set_name(v.box, v.spec->name);
  }
  return b;
}

}  // namespace

}  // namespace sillage
