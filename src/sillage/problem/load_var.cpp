// [var.NAME]: a variable's kind, dimension and initial bounds (constants,
// expressions of t, gates at given times, slices and gates from a table).
#include "sillage/problem/problem_loader.h"

#include <tuple>

#include "sillage/expr/function.h"
#include "sillage/expr/parser.h"
#include "sillage/expr/tape.h"
#include "sillage/problem/var_refs.h"

namespace sillage::detail {

void ProblemLoader::check_bound(const BoundSpec& b, bool of_t) {
  if (b.expr.empty()) return;
  const std::vector<std::string> vars = of_t ? std::vector<std::string>{"t"} : std::vector<std::string>{};
  const std::string expected = of_t ? "an expression of t such as \"sin(t) + [-0.1, 0.1]\""
                                     : "a constant expression such as \"[-1, 1]\" or \"pi/2 + [-0.01, 0.01]\"";
  try {
    (void)detail::parse_expr(vars, b.expr);
  } catch (const ParseError& e) {
    throw rejected_expression(b.pos, "the bound", b.expr, b.expr, e, expected);
  }
  // Empty over the whole time domain ("1/0"): no value at all, a mistake of
  // the file, not a problem without solution.
  const IntervalVector at = of_t ? IntervalVector{Interval(p_.time.t0, p_.time.tf)} : IntervalVector(0);
  if (Function(vars, b.expr).eval(at).is_empty())
    throw ProblemError(b.pos, "the bound \"" + b.expr + "\", which is empty (undefined" +
                                  (of_t ? " at every t of the domain)" : ")"),
                       expected);
}

std::vector<BoundSpec> ProblemLoader::read_bounds(const Fields& f, const toml::node& n, std::size_t dim, bool of_t) {
  std::vector<BoundSpec> out;
  const std::string expected = dim == 1 ? "a bound (string or number) or an array of 1 bound"
                                        : "an array of " + std::to_string(dim) + " bounds (\"\" for the whole line)";
  if (n.is_array()) {
    const toml::array& a = *n.as_array();
    if (a.size() != dim) throw ProblemError(doc_.pos(n), describe(n), expected);
    for (const toml::node& e : a) out.push_back({f.bound_text(e), doc_.pos(e)});
  } else if (dim == 1) {
    out.push_back({f.bound_text(n), doc_.pos(n)});
  } else {
    throw ProblemError(doc_.pos(n), describe(n), expected);
  }
  for (BoundSpec& b : out) {
    if (b.pos.line > 0 && doc_.lines[b.pos.line - 1][b.pos.column - 1] == '"') b.pos.column += 1;
    check_bound(b, of_t);
  }
  return out;
}

void ProblemLoader::read_var(const std::string& name, const toml::key& key, const toml::node& node) {
  const SourcePos kp = doc_.pos(key.source());
  if (!valid_name(name))
    throw ProblemError(kp, "the variable name '" + name + "'",
                       "an identifier (letters, digits, _; not __, not a function name)");
  if (name == "t" || name == "dt")  // a bound or a table's value reads them as the time and the slice's width
    throw ProblemError(kp, "the variable name '" + name + "'",
                       "a name other than t and dt (the time and the slice width in bounds and table values)");
  const Fields f(doc_, Fields(doc_, toml::table{}, "", {}).table(node, "a table [var." + name + "]"),
                 "[var." + name + "]", {"kind", "dim", "value", "at", "slices", "gates", "angle", "unit"});
  VarSpec v;
  v.name = name;
  v.pos = kp;
  const toml::node& k = f.require("kind", "\"tube\", \"tube_vector\", \"interval\" or \"box\"");
  const std::string ks = f.string(k, "\"tube\", \"tube_vector\", \"interval\" or \"box\"");
  if (ks == "tube") v.kind = VarKind::Tube;
  else if (ks == "tube_vector") v.kind = VarKind::TubeVector;
  else if (ks == "interval") v.kind = VarKind::Interval;
  else if (ks == "box") v.kind = VarKind::Box;
  else throw ProblemError(doc_.pos(k), describe(k), "\"tube\", \"tube_vector\", \"interval\" or \"box\"");
  const bool vector = v.kind == VarKind::TubeVector || v.kind == VarKind::Box;
  if (const toml::node* d = f.find("dim")) {
    const std::int64_t n = f.integer(*d, "an integer dimension");
    if (vector ? (n < 1 || n > 1000) : n != 1)
      throw ProblemError(doc_.pos(*d), "dim = " + std::to_string(n),
                         vector ? "a dimension from 1 to 1000" : "no dim (or dim = 1) for a " + ks);
    v.dim = static_cast<std::size_t>(n);
  } else if (vector) {
    throw ProblemError(kp, "no 'dim' for the " + ks + " '" + name + "'", "dim = N");
  }
  if (const toml::node* u = f.find("unit")) v.unit = f.string(*u, "a unit for the reports, e.g. \"m\"");
  v.value.assign(v.dim, BoundSpec{});
  if (const toml::node* val = f.find("value")) v.value = read_bounds(f, *val, v.dim, v.is_tube());
  if (const toml::node* at = f.find("at")) {
    if (!v.is_tube()) throw ProblemError(doc_.pos(*at), "'at' for the " + ks + " '" + name + "'", "'at' on tubes only");
    for (const toml::node& g : f.array(*at, "an array of {t = time, value = bounds}")) {
      const Fields gf(doc_, f.table(g, "a table {t = time, value = bounds}"), "an 'at' of " + name, {"t", "value"});
      GateSpec gs;
      gs.pos = doc_.pos(g);
      const toml::node& tn = gf.require("t", "a time in the domain");
      gs.t = gf.number(tn, "a time (number)");
      std::tie(gs.t_lo, gs.t_hi) = gf.number_as_written(tn, "a time (number)");
      if (gs.t < p_.time.t0 || gs.t > p_.time.tf)
        throw ProblemError(doc_.pos(tn), "t = " + doc_.raw(tn) + " outside the time domain",
                           "a time in [" + number_text(p_.time.t0) + ", " + number_text(p_.time.tf) + "]");
      gs.value = read_bounds(gf, gf.require("value", "the bounds at t"), v.dim, false);
      v.at.push_back(std::move(gs));
    }
  }
  if (const toml::node* an = f.find("angle")) {
    if (!an->is_boolean()) throw ProblemError(doc_.pos(*an), describe(*an), "true (values known modulo 2 pi) or false");
    v.angle = an->as_boolean()->get();
    if (v.angle && v.kind != VarKind::Tube)
      throw ProblemError(doc_.pos(*an), "angle = true for the " + ks + " '" + name + "'", "angle = true on a scalar tube");
  }
  if (const toml::node* sn = f.find("slices")) v.slices = read_from_table(f, *sn, v, false);
  if (const toml::node* gn = f.find("gates")) v.gates = read_from_table(f, *gn, v, true);
  if (p_.table(name)) throw ProblemError(kp, "the variable '" + name + "' named as a data table", "distinct names");
  p_.vars.push_back(std::move(v));
}

// slices = {data, value} (gates = false): slice k from row k, an expression of
// its columns and dt; gates = {data, value} (gates = true): the gate at time
// point k from row k, an expression of its columns. Both with [time] points.
SliceDataSpec ProblemLoader::read_from_table(const Fields& f, const toml::node& sn, const VarSpec& v, bool gates) {
  const std::string key = gates ? "gates" : "slices";
  if (v.kind != VarKind::Tube)
    throw ProblemError(doc_.pos(sn), "'" + key + "' for the " + std::string(kind_name(v.kind)) + " '" + v.name + "'",
                       "'" + key + "' on a tube");
  if (p_.time.points.empty())
    throw ProblemError(doc_.pos(sn), "'" + key + "' without time points from data", "[time] points = {data, column}");
  const Fields sf(doc_, f.table(sn, "a table {data = \"NAME\", value = \"expression\"}"), "the " + key + " of " + v.name,
                  {"data", "value", "held"});
  SliceDataSpec s;
  const std::size_t rows = gates ? p_.time.points.size() : p_.time.points.size() - 1;
  const std::string per = gates ? "one row per time point" : "one row per slice";
  const toml::node& dn = sf.require("data", "a [data.NAME] table, " + per);
  const DataSpec& d = data_table(sf, dn);
  s.data = d.name;
  // held = true: the time points' own table, each row held until the next (a
  // command): slice k from row k, the last row only ends the domain.
  if (const toml::node* hn = sf.find("held")) {
    if (!hn->is_boolean()) throw ProblemError(doc_.pos(*hn), describe(*hn), "true or false");
    s.held = hn->as_boolean()->get();
    if (s.held && (gates || d.name != p_.time.points_data))
      throw ProblemError(doc_.pos(*hn), "held = true on " + (gates ? std::string("gates") : "the table '" + d.name + "'"),
                         "held = true on slices from the [time] points' own table ('" + p_.time.points_data + "')");
  }
  if (d.table.nb_rows() != rows + (s.held ? 1 : 0))
    throw ProblemError(doc_.pos(dn), "the table '" + d.name + "' of " + std::to_string(d.table.nb_rows()) + " rows",
                       per + ": " + std::to_string(rows) + " rows" +
                           (!gates && d.name == p_.time.points_data
                                ? " (held = true if each row of the time points' own table holds until the next, "
                                  "a command)"
                                : ""));
  const std::string of = gates ? "an expression of the row's columns" : "an expression of the row's columns and dt";
  const toml::node& vn = sf.require("value", of);
  s.value = {sf.bound_text(vn), detail::shifted(doc_.pos(vn), vn.is_string() ? 1 : 0)};
  std::vector<std::string> names = d.table.columns();
  if (!gates) names.push_back("dt");
  const Expr e = [&] {
    try {
      return detail::parse_expr(names, s.value.expr);
    } catch (const ParseError& err) {
      throw rejected_expression(s.value.pos, "the value", s.value.expr, s.value.expr, err,
                                "an expression of the columns of '" + d.name + "'" + (gates ? "" : " and dt"));
    }
  }();
  for (const Expr& x : detail::topological_order({e}))  // the columns it reads: numbers only
    if (x.op() == Op::Var && (gates || x.node().name != "dt")) require_column(s.value.pos, x.node().name, d.name, d.table);
  return s;
}

}  // namespace sillage::detail
