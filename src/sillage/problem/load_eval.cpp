// [[constraint]] kind = "eval": evaluations at the times of a table's rows and their observation.
#include "sillage/problem/problem_loader.h"

#include <charconv>
#include <cstdio>
#include <set>
#include <span>

#include "sillage/expr/function.h"
#include "sillage/problem/eval_rows.h"

namespace sillage::detail {

namespace {

// The kept rows of c whose time lies wholly outside the domain: an error
// naming the first (file and line) unless c.skip_outside, else counted.
std::size_t outside_rows(const ConstraintSpec& c, const DataSpec& d, const Interval& domain) {
  if (c.time_columns.empty()) return 0;
  const Interval terr = Function({"t"}, c.time_error).eval(IntervalVector{Interval(0)});
  std::size_t n = 0;
  for (std::size_t row = 0; row < d.table.nb_rows(); ++row) {
    const std::span<const double> values = d.table.row(row);
    if (!eval_row_kept(c, d.table, values) || !eval_row_time(c, d.table, values, terr, domain).is_empty()) continue;
    if (!c.skip_outside)
      throw ProblemError(c.pos, "row " + std::to_string(row) + " of '" + c.data + "' (" + d.table.where(row) + ") at " +
                                    c.time_columns[0] + " = " + cell_text(values[d.table.column(c.time_columns[0])]) +
                                    ", outside the time domain " + domain.str(),
                         "rows within [t0, tf] (outside = \"skip\" skips the others, counted by sillage check)");
    ++n;
  }
  return n;
}

}  // namespace

void ProblemLoader::read_eval(const Fields& f, ConstraintSpec& c, const std::string& where) {
  c.kind = ConstraintKind::Eval;
  const toml::node& dn = f.require("data", "the name of a [data.NAME] table");
  c.data = f.string(dn, "a data table name (string)");
  const DataSpec* d = p_.table(c.data);
  if (!d) {
    std::string names;
    for (const DataSpec& x : p_.data) names += (names.empty() ? "" : ", ") + x.name;
    throw ProblemError(doc_.pos(dn), "the unknown table '" + c.data + "'", "a [data.NAME] table (" + names + ")");
  }
  std::vector<const VarSpec*> ys;
  for (const toml::node* n : one_or_many(f, f.require("y", "a tube name or an array of them"),
                                         "a tube name or an array of them")) {
    const VarSpec& y = tube_var(f, *n);
    for (const VarSpec* o : ys)
      if (o == &y) throw ProblemError(doc_.pos(*n), "'" + y.name + "' twice", "distinct tubes in y");
    ys.push_back(&y);
    c.ys.push_back(y.name);
  }
  c.vs.assign(ys.size(), "");
  if (const toml::node* vn = f.find("v")) {
    const auto vs = one_or_many(f, *vn, "a derivative tube per tube of y");
    if (vs.size() != ys.size())
      throw ProblemError(doc_.pos(*vn), std::to_string(vs.size()) + " derivative(s)",
                         std::to_string(ys.size()) + " (one per tube of y, \"\" for none)");
    for (std::size_t j = 0; j < vs.size(); ++j) {
      if (vs[j]->is_string() && vs[j]->as_string()->get().empty()) continue;
      const VarSpec& v = tube_var(f, *vs[j]);
      if (v.dim != ys[j]->dim || v.kind != ys[j]->kind)
        throw ProblemError(doc_.pos(*vs[j]), "'" + v.name + "'",
                           "a derivative of the kind and dimension of '" + ys[j]->name + "'");
      c.vs[j] = v.name;
    }
  }
  c.x = c.ys[0];
  c.v = c.vs[0];
  auto column = [&](const toml::node& n) {
    const std::string col = f.string(n, "a column name (string)");
    require_column(doc_.pos(n), col, c.data, d->table);
    return col;
  };
  if (const toml::node* tn = f.find("time")) {
    const std::string expected = "a time column, or two columns [lb, ub]";
    const auto cols = one_or_many(f, *tn, expected);
    if (cols.size() > 2) throw ProblemError(doc_.pos(*tn), describe(*tn), expected);
    for (const toml::node* n : cols) c.time_columns.push_back(column(*n));
  }
  if (const toml::node* te = f.find("time_error")) {
    if (f.number(*te, "a time error >= 0") < 0) throw ProblemError(doc_.pos(*te), "a negative time error", "a time error >= 0");
    if (c.time_columns.empty())
      throw ProblemError(doc_.pos(*te), "a time error without a time column", "time = \"column\" with it");
    c.time_error = f.bound_text(*te);
  }
  if (const toml::node* er = f.find("errors")) {
    for (auto&& [key, node] : f.table(*er, "a table {column = error}")) {
      require_column(doc_.pos(key.source()), std::string(key.str()), c.data, d->table);
      if (f.number(node, "an error >= 0 (number)") < 0)
        throw ProblemError(doc_.pos(node), "a negative error", "an error >= 0");
      c.errors[std::string(key.str())] = f.bound_text(node);
    }
  }
  if (const toml::node* wn = f.find("where")) {
    for (auto&& [key, node] : f.table(*wn, "a table {column = value}")) {
      require_column(doc_.pos(key.source()), std::string(key.str()), c.data, d->table);
      const std::string expected = "a value of the column (number) or a range [lo, hi]";
      if (node.is_array()) {
        const toml::array& a = *node.as_array();
        if (a.size() != 2) throw ProblemError(doc_.pos(node), describe(node), expected);
        const double lo = f.number(*a.get(0), expected), hi = f.number(*a.get(1), expected);
        if (!(lo <= hi)) throw ProblemError(doc_.pos(node), describe(node), "a range [lo, hi] with lo <= hi");
        c.where[std::string(key.str())] = {lo, hi};
      } else {
        const double v = f.number(node, expected);
        c.where[std::string(key.str())] = {v, v};
      }
    }
  }
  if (const toml::node* g = f.find("gates")) {
    if (!g->is_boolean()) throw ProblemError(doc_.pos(*g), describe(*g), "true or false");
    c.gates = g->as_boolean()->get();
  }
  const DataSpec* joined = nullptr;
  std::set<std::string> in_both;  // columns of both tables, besides the join's
  if (const toml::node* jn = f.find("join")) {
    const Fields jf(doc_, f.table(*jn, "a table {data = \"NAME\", on = \"column\"}"), where + " join", {"data", "on"});
    joined = &data_table(jf, jf.require("data", "a [data.NAME] table"));
    const toml::node& on = jf.require("on", "a column of both tables");
    c.join_on = jf.string(on, "a column name (string)");
    c.join_data = joined->name;
    if (!d->table.has_column(c.join_on) || !joined->table.has_column(c.join_on))
      throw ProblemError(doc_.pos(on), "the column '" + c.join_on + "'", "a column of both '" + c.data + "' and '" + joined->name + "'");
    require_column(doc_.pos(on), c.join_on, c.data, d->table);
    require_column(doc_.pos(on), c.join_on, joined->name, joined->table);
    for (const auto& col : joined->table.columns())  // an error if the observation reads one (below)
      if (col != c.join_on && d->table.has_column(col)) in_both.insert(col);
    check_join_keys(c, d->table, joined->table, doc_.pos(*jn));  // here, so that sillage check says it
  }
  const auto has_column = [&](const std::string& n) { return d->table.has_column(n) || (joined && joined->table.has_column(n)); };
  // In the observation: the evaluated values are named as their tubes, the columns by name.
  const auto y_of = [&](const std::string& n) -> const VarSpec* {
    for (const VarSpec* y : ys)
      if (y->name == n) return y;
    return nullptr;
  };
  auto dims = [&](const std::string& n) -> std::optional<std::size_t> {
    if (const VarSpec* y = y_of(n)) return y->dim;
    if (in_both.count(n))
      throw ProblemError(c.expr_pos, "the column '" + n + "' of both '" + c.data + "' and '" + joined->name + "'",
                         "a column of one table only in the observation (besides '" + c.join_on + "')");
    if (has_column(n)) {  // a column the observation reads: numbers only
      const DataSpec& t = d->table.has_column(n) ? *d : *joined;
      require_column(c.expr_pos, n, t.name, t.table);
      return 1;
    }
    const VarSpec* v = p_.var(n);
    if (v && !v->is_tube()) return v->dim;
    return std::nullopt;
  };
  auto vec = [&](const std::string& n) {
    if (const VarSpec* y = y_of(n)) return y->kind == VarKind::TubeVector;
    const VarSpec* v = p_.var(n);
    return !has_column(n) && v && v->kind == VarKind::Box;
  };
  std::string known, names;
  for (const VarSpec* y : ys) {
    known += y->name + (y->kind == VarKind::TubeVector ? "[i]" : "") + " (the value " + y->name + "(t)), ";
    names += (names.empty() ? "" : ", ") + y->name;
  }
  const auto columns_of = [](const DataSpec& t) { return "the columns of '" + t.name + "' (" + column_list(t.table) + ")"; };
  known += columns_of(*d) + (joined ? " and " + columns_of(*joined) : "");
  for (const VarSpec& v : p_.vars)
    if (!v.is_tube()) known += ", " + v.name;
  read_expr(f, c, dims, vec, known);
  std::vector<std::string> cols = d->table.columns();
  if (joined) cols.insert(cols.end(), joined->table.columns().begin(), joined->table.columns().end());
  for (const auto& col : cols)
    if (p_.var(col) && !y_of(col))
      throw ProblemError(c.pos, "the column '" + col + "' named as a variable", "distinct names in an eval observation");
  if (const toml::node* on = f.find("outside")) {
    const std::string v = f.string(*on, "\"error\" or \"skip\"");
    if (v != "error" && v != "skip") throw ProblemError(doc_.pos(*on), "\"" + v + "\"", "\"error\" or \"skip\"");
    c.skip_outside = v == "skip";
  }
  c.nb_outside = outside_rows(c, *d, Interval(p_.time.t0, p_.time.tf));
  read_outliers(f, c);
  c.label = where + ": " + c.expr + " = 0 at " + names + "(" +
            (c.time_columns.empty()       ? std::string("t unknown")
             : c.time_columns.size() == 1 ? c.time_columns[0]
                                          : "[" + c.time_columns[0] + ", " + c.time_columns[1] + "]") +
            ") for every row of '" +
            c.data + "'" + (c.where.empty() ? "" : " kept by 'where'") + outliers_text(c);
}

void ProblemLoader::read_outliers(const Fields& f, ConstraintSpec& c) {
  const toml::node* q = f.find("q");
  const toml::node* w = f.find("q_window");
  const toml::node* r = f.find("q_rows");
  if (!q) {
    if (w || r) throw ProblemError(doc_.pos(w ? *w : *r), w ? "q_window without q" : "q_rows without q", "q = N, the rows that may be wrong");
    return;
  }
  const std::int64_t n = f.integer(*q, "a number of rows that may be wrong (an integer >= 0)");
  if (n < 0) throw ProblemError(doc_.pos(*q), "q = " + doc_.raw(*q), "a number of rows that may be wrong (an integer >= 0)");
  c.q = static_cast<std::size_t>(n);
  if (w && r) throw ProblemError(doc_.pos(*r), "both q_window and q_rows", "one of them: per W seconds or per M rows");
  if (w) {
    c.q_window = f.number(*w, "seconds > 0");
    if (!(c.q_window > 0)) throw ProblemError(doc_.pos(*w), "q_window = " + doc_.raw(*w), "seconds > 0");
    if (c.time_columns.empty()) throw ProblemError(doc_.pos(*w), "q_window without a time column", "time = \"column\" with it");
  }
  if (r) {
    const std::int64_t m = f.integer(*r, "a number of rows > q");
    if (m <= n) throw ProblemError(doc_.pos(*r), "q_rows = " + doc_.raw(*r), "a number of rows > q = " + std::to_string(n));
    c.q_rows = static_cast<std::size_t>(m);
  }
}

std::string outliers_text(const ConstraintSpec& c) {
  if (!c.q) return "";
  char buf[96];
  if (c.q_window > 0) std::snprintf(buf, sizeof buf, ", at most %zu wrong in any %g s", *c.q, c.q_window);
  else if (c.q_rows > 0) std::snprintf(buf, sizeof buf, ", at most %zu wrong in any %zu rows", *c.q, c.q_rows);
  else std::snprintf(buf, sizeof buf, ", at most %zu wrong", *c.q);
  return buf;
}

}  // namespace sillage::detail
