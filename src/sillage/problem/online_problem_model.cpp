// OnlineProblem's model: a problem file's tube variables and constraints
// declared on its OnlineEstimator (online_problem.h says what runs online).
#include <algorithm>
#include <cmath>

#include "online_problem_impl.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/dynamics/ctc_second_deriv.h"
#include "sillage/error.h"
#include "sillage/problem/build_network.h"
#include "sillage/problem/eval_rows.h"

namespace sillage {

using detail::bound_of;
using detail::EvalPlan;
using detail::kInf;
using detail::Waiting;
using detail::not_online;

namespace detail {

ProblemError not_online(const SourcePos& pos, const std::string& found, const std::string& why) {
  return ProblemError(pos, found + " (" + why + ")", "what runs online (docs/online.md, \"From a problem file\")");
}

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

}  // namespace detail

namespace {

Interval error_of(const std::string& text, const SourcePos& pos) {
  const Interval e = text.empty() ? Interval(0) : Function({"t"}, text).eval(IntervalVector{Interval(0)});
  if (e.is_empty() || e.lb() < 0) throw ProblemError(pos, "the error " + text, "an error >= 0");
  return e;
}

// A constant bound's value (the loader checked that it is one).
Interval constant_of(const BoundSpec& b) { return Function({"t"}, b.expr).eval(IntervalVector{Interval(0)}); }
// z ∈ box: a state's value stated at a time.
std::shared_ptr<const Ctc> in_box(const IntervalVector& z) {
  std::vector<std::string> names;
  std::string text = z.size() > 1 ? "(" : "";
  for (std::size_t i = 0; i < z.size(); ++i) {
    names.push_back("z" + std::to_string(i));
    text += (i ? ", " : "") + names.back();
  }
  return std::make_shared<CtcFunction>(Function(names, z.size() > 1 ? text + ")" : text), z);
}

}  // namespace

void detail::OnlineProblemImpl::declare_vars() {
  for (const VarSpec& v : p.vars) {
    if (!v.is_tube()) throw not_online(v.pos, std::string(kind_name(v.kind)) + " " + v.name, "a constant of the whole run");
    if (v.gates) throw not_online(v.pos, v.name + " gates = {data = ...}", "a value per time point from a table");
    IntervalVector x0(v.dim);
    for (const GateSpec& g : v.at) {
      IntervalVector z(v.dim);
      for (std::size_t i = 0; i < v.dim; ++i) z[i] = g.value[i].expr.empty() ? Interval() : constant_of(g.value[i]);
      if (g.t_hi <= p.time.t0) x0 &= z;  // at t0, or before: the domain's start
      else waiting.push_back({Interval(std::max(g.t_lo, p.time.t0), g.t_hi), {v.name}, in_box(z)});
    }
    if (v.slices) {
      if (!v.at.empty()) throw not_online(v.at[0].pos, v.name + " at t = ...", "an input's value comes from its rows");
      if (!clock.empty() && clock != v.slices->data)
        throw not_online(v.pos, v.name + " slices from " + v.slices->data,
                         "the periods come from one table, here " + clock);
      clock = v.slices->data;
      if (v.slices->held)  // online, a period's row arrives with its end
        throw not_online(v.pos, v.name + " slices with held = true", "slices from a table of one row per period");
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

std::string detail::OnlineProblemImpl::ref_name(const VarRef& r, const SourcePos& pos) const {
  const VarSpec* v = p.var(r.var);
  if (!v || !v->is_tube()) throw not_online(pos, r.var, "not a tube variable");
  return v->kind == VarKind::Tube ? v->name : v->name + "[" + std::to_string(r.component) + "]";
}

void detail::OnlineProblemImpl::parse_inputs() {
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

void detail::OnlineProblemImpl::declare_constraints() {
  const auto dims = [&](const std::string& n) -> std::optional<std::size_t> {
    const VarSpec* v = p.var(n);
    return v ? std::optional<std::size_t>(v->dim) : std::nullopt;
  };
  const auto vec = [&](const std::string& n) {
    const VarSpec* v = p.var(n);
    return v && (v->kind == VarKind::TubeVector || v->kind == VarKind::Box);
  };
  for (const VarSpec& v : p.vars)  // its deriv and evals online read values as real numbers
    if (v.angle) throw not_online(v.pos, "the angle '" + v.name + "' (angle = true)", "angle tubes are not online yet");
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
      case ConstraintKind::Python:
        throw not_online(c.pos, c.label, "a Python contractor runs in batch solves only (sillage.solve)");
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

bool detail::OnlineProblemImpl::implied_deriv(const std::string& y) const {
  for (const ConstraintSpec& c : p.constraints)
    if (c.kind == ConstraintKind::Eval)
      for (std::size_t j = 0; j < c.ys.size(); ++j)
        if (c.ys[j] == y && !c.vs[j].empty()) return true;
  return false;
}

void detail::OnlineProblemImpl::plan_eval(const ConstraintSpec& c, std::set<std::string>& with_deriv) {
  if (c.q) throw not_online(c.pos, c.label, "outliers (q) are not online yet");
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

}  // namespace sillage
