#include "sillage/problem/bound_audit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "sillage/error.h"
#include "sillage/problem/angle_terms.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/tube/trajectory.h"

namespace sillage {

double audit_percent(const AuditLine& l) { return 100.0 * l.used / l.allowed; }

std::string audit_text(const AuditLine& l) {
  char buf[600];
  const std::string unit = l.unit.empty() ? "" : " " + l.unit;
  if (std::isnan(l.used)) {
    std::snprintf(buf, sizeof buf, "%s: %.4g%s allowed, not measurable from the truth (%s)", l.name.c_str(), l.allowed,
                  unit.c_str(), l.how.c_str());
  } else {
    const double p = audit_percent(l);
    std::snprintf(buf, sizeof buf, "%s: max %.4g%s of %.4g allowed (%.0f %%; %s)%s", l.name.c_str(), l.used,
                  unit.c_str(), l.allowed, p, l.how.c_str(), p > 100.0 ? "  <-- VIOLATED" : "");
  }
  return buf;
}

namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

// The truth of a problem: per variable with truth columns, one trajectory per component, and
// the truth's time points within [t0, tf].
struct Truth {
  std::map<std::string, std::vector<Trajectory>> of;
  std::vector<double> times;
  // The truth of var[i] at t; none outside its domain or without a truth.
  std::optional<double> at(const std::string& var, std::size_t i, double t) const {
    const auto it = of.find(var);
    if (it == of.end() || i >= it->second.size() || !it->second[i].domain().contains(t)) return std::nullopt;
    const Interval x = it->second[i](t);
    if (x.is_empty() || !x.is_bounded()) return std::nullopt;
    return x.mid();
  }
};

Truth truth_of(const Problem& p) {
  Truth tr;
  const TruthSpec& spec = *p.output.truth;
  const CsvTable& t = p.table(spec.data)->table;
  const std::vector<double> times = t.values(spec.time_column);
  for (const auto& [var, cols] : spec.columns)
    for (const std::string& c : cols) tr.of[var].emplace_back(times, t.values(c));
  for (const double time : times)
    if (time >= p.time.t0 && time <= p.time.tf) tr.times.push_back(time);
  return tr;
}

Interval bound_at(const BoundSpec& b, double t) { return Function({"t"}, b.expr).eval(IntervalVector{Interval(t)}); }

std::string comp(const VarSpec& v, std::size_t i) {
  return v.kind == VarKind::TubeVector ? v.name + "[" + std::to_string(i) + "]" : v.name;
}

// The worst use of a bound over samples: used |x - mid| of rad, kept where used / allowed is largest.
struct Worst {
  double used = NAN, allowed = NAN, ratio = -1;
  std::string where;
  void add(double u, double a, const std::string& w) {
    const double r = a > 0 ? u / a : (u > 0 ? INFINITY : 0);
    if (r > ratio) used = u, allowed = a, ratio = r, where = w;
  }
};

// How far the truth x is from the middle m of a bound: modulo 2π for an angle.
double off(double x, double m, bool angle) { return std::abs(angle ? std::remainder(x - m, 2 * M_PI) : x - m); }

// The [var] bounds: its value over the truth's times, each 'at' at its time.
void audit_var(const VarSpec& v, const Truth& tr, std::vector<AuditLine>& out) {
  if (!tr.of.count(v.name)) return;
  for (std::size_t i = 0; i < v.dim; ++i) {
    if (!v.value.empty() && !v.value[i].expr.empty()) {
      Worst w;
      for (const double t : tr.times) {
        const std::optional<double> x = tr.at(v.name, i, t);
        const Interval b = bound_at(v.value[i], t);
        if (x && b.is_bounded() && !b.is_empty()) w.add(off(*x, b.mid(), v.angle), b.rad(), "t = " + number(t));
      }
      if (w.ratio >= 0)
        out.push_back({"[var." + v.name + "] value of " + comp(v, i), v.unit, w.allowed, w.used,
                       "truth vs the middle of the bound, worst at " + w.where + "; " + v.value[i].pos.str()});
    }
    for (const GateSpec& g : v.at) {
      if (g.value[i].expr.empty()) continue;  // "": the whole line, no bound
      const Interval b = bound_at(g.value[i], g.t);
      const std::optional<double> x = tr.at(v.name, i, g.t);
      if (b.is_empty() || !b.is_bounded()) continue;
      out.push_back({"[var." + v.name + "] " + comp(v, i) + " at t = " + number(g.t), v.unit, b.rad(),
                     x ? off(*x, b.mid(), v.angle) : NAN,
                     std::string(x ? "truth vs the middle of the bound" : "no truth at that time") + "; " + g.pos.str()});
    }
  }
}

// An eval's name in the audit: "constraint 3 (eval) on 'ranges' where subject_id = 6" (its
// label without the expression, which its place in the file gives).
std::string eval_name(const ConstraintSpec& c) {
  std::string n = c.label.substr(0, c.label.find(": ")) + " on '" + c.data + "'";
  for (const auto& [col, range] : c.where)
    n += (n.find(" where ") == std::string::npos ? " where " : ", ") + col +
         (range.first == range.second ? " = " + number(range.first)
                                      : " in [" + number(range.first) + ", " + number(range.second) + "]");
  return n;
}

// One eval constraint: each kept row's expression with the truth in place of its variables.
void audit_eval(const Problem& p, const ConstraintSpec& c, const Truth& tr, std::vector<AuditLine>& out) {
  const detail::RewrittenExpr r = detail::eval_observation(p, c);
  std::set<std::string> angle_ids;  // an equation with angle terms holds modulo 2π
  for (const detail::VarRef& ref : r.refs)
    if (p.var(ref.var) && p.var(ref.var)->angle) angle_ids.insert(ref.id);
  const bool modulo = detail::has_angle_terms(r.text, angle_ids, c.expr_pos, c.label);
  const CsvTable& table = p.table(c.data)->table;
  const CsvTable* joined = c.join_data.empty() ? nullptr : &p.table(c.join_data)->table;
  const auto column = [&](const std::string& n) { return table.has_column(n) || (joined && joined->has_column(n)); };
  std::string missing;
  for (const detail::VarRef& ref : r.refs)
    if (!column(ref.var) && !tr.of.count(ref.var) && missing.find("'" + ref.var + "'") == std::string::npos)
      missing += (missing.empty() ? "'" : ", '") + ref.var + "'";
  if (!missing.empty()) {
    out.push_back({eval_name(c), "", NAN, NAN, "reads " + missing + ", which the truth does not give; " + c.pos.str()});
    return;
  }
  const Function f(r.ids(), r.text);
  const Interval terr = Function({"t"}, c.time_error).eval(IntervalVector{Interval(0)});
  std::map<std::string, Interval> errs;
  for (const auto& [col, text] : c.errors) errs[col] = Function({"t"}, text).eval(IntervalVector{Interval(0)});
  std::map<double, std::size_t> join_rows;
  if (joined)
    for (std::size_t k = 0; k < joined->nb_rows(); ++k) join_rows.emplace(joined->row(k)[joined->column(c.join_on)], k);
  Worst w;
  std::size_t rows = 0;
  IntervalVector args(r.refs.size());
  for (std::size_t row = 0; row < table.nb_rows(); ++row) {
    const std::span<const double> values = table.row(row);
    if (!detail::eval_row_kept(c, table, values)) continue;
    const Interval rt = detail::eval_row_time(c, table, values, terr, Interval(p.time.t0, p.time.tf));
    if (rt.is_empty() || rt.is_unbounded()) continue;
    std::span<const double> join_values;
    if (joined) {
      const auto j = join_rows.find(values[table.column(c.join_on)]);
      if (j == join_rows.end()) continue;  // the loader rejects such a row
      join_values = joined->row(j->second);
    }
    // The best of 9 times of the row's window: the truth needs only one of them.
    std::optional<std::pair<double, double>> best;  // used, allowed
    for (int s = 0; s <= 8; ++s) {
      const double t = rt.is_degenerate() ? rt.lb() : rt.lb() + rt.diam() * s / 8;
      bool known = true;
      for (std::size_t k = 0; k < r.refs.size() && known; ++k) {
        const detail::VarRef& ref = r.refs[k];
        if (column(ref.var)) {
          const double v = table.has_column(ref.var) ? values[table.column(ref.var)] : join_values[joined->column(ref.var)];
          const auto e = errs.find(ref.var);
          args[k] = detail::csv_cell(v) + Interval(-1, 1) * (e == errs.end() ? Interval(0) : e->second);
        } else if (const std::optional<double> x = tr.at(ref.var, ref.component, t)) {
          args[k] = Interval(*x);
        } else {
          known = false;
        }
      }
      if (known) {
        const Interval y = f.eval(args);
        const double used = off(y.mid(), 0, modulo);
        if (!y.is_empty() && y.is_bounded() && (!best || used / y.rad() < best->first / best->second))
          best = {used, y.rad()};
      }
      if (rt.is_degenerate()) break;
    }
    if (!best) continue;
    ++rows;
    w.add(best->first, best->second, c.data + " line " + std::to_string(table.line(row)));
  }
  if (rows == 0) {
    out.push_back({eval_name(c), "", NAN, NAN, "no row within the truth's time span; " + c.pos.str()});
    return;
  }
  out.push_back({eval_name(c), "", w.allowed, w.used,
                 "the expression's value at the truth vs the middle of its range, over " + std::to_string(rows) +
                     " rows, worst " + w.where + "; " + c.pos.str()});
}

}  // namespace

std::vector<AuditLine> audit_problem(const Problem& p) {
  std::vector<AuditLine> out;
  if (!p.output.truth) return out;
  const Truth tr = truth_of(p);
  // The audit reports on a solve: a bound it cannot evaluate is a line saying so, never an error.
  const auto guarded = [&](const std::string& what, const SourcePos& pos, const auto& audit) {
    try {
      audit();
    } catch (const Error& e) {
      out.push_back({what, "", NAN, NAN, std::string("not audited: ") + e.what() + "; " + pos.str()});
    }
  };
  for (const VarSpec& v : p.vars) guarded("[var." + v.name + "]", v.pos, [&] { audit_var(v, tr, out); });
  for (const ConstraintSpec& c : p.constraints)
    if (c.kind == ConstraintKind::Eval) guarded(c.label, c.pos, [&] { audit_eval(p, c, tr, out); });
  return out;
}

}  // namespace sillage
