#include "sillage/problem/load_problem.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sillage/expr/parser.h"
#include "sillage/problem/toml_fields.h"
#include "sillage/problem/var_refs.h"

namespace sillage {

using detail::rewrite_refs;
using detail::shifted;

using detail::describe;
using detail::Document;
using detail::Fields;

namespace {

std::string fnv1a_hex(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

bool valid_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return s.find("__") == std::string::npos && !detail::is_reserved_name(s);
}

class Loader {
 public:
  Loader(const std::string& text, const std::string& path) {
    p_.file = path;
    p_.text = text;
    p_.hash = fnv1a_hex(text);
    doc_.file = path;
    std::istringstream is(text);
    for (std::string l; std::getline(is, l);) doc_.lines.push_back(l);
    base_ = std::filesystem::path(path).parent_path();
  }

  Problem run() {
    toml::table root;
    try {
      root = toml::parse(p_.text, p_.file);
    } catch (const toml::parse_error& e) {
      throw ProblemError(doc_.pos(e.source()), "invalid TOML: " + std::string(e.description()),
                         "a TOML file (https://toml.io)");
    }
    const Fields top(doc_, root, "the file", {"time", "data", "var", "constraint", "output", "network"});
    if (const toml::node* d = top.find("data"))
      for (auto&& [key, node] : top.table(*d, "tables [data.NAME]")) read_data(std::string(key.str()), key, node);
    read_time(top.table(top.require("time", "a table [time] with domain = [t0, tf]"), "a table [time]"));
    const toml::node& vars = top.require("var", "tables [var.NAME]");
    for (auto&& [key, node] : top.table(vars, "tables [var.NAME]")) read_var(std::string(key.str()), key, node);
    const toml::node& cs = top.require("constraint", "one or more [[constraint]] tables");
    for (const toml::node& c : top.array(cs, "[[constraint]] tables")) read_constraint(top, c);
    if (const toml::node* o = top.find("output")) read_output(top.table(*o, "a table [output]"));
    if (const toml::node* n = top.find("network")) read_network(top.table(*n, "a table [network]"));
    return std::move(p_);
  }

 private:
  // ---- [time] ----
  void read_time(const toml::table& t) {
    const Fields f(doc_, t, "[time]", {"domain", "delta", "points"});
    if (const toml::node* pn = f.find("points")) return read_time_points(f, *pn);
    const toml::node& d = f.require("domain", "[t0, tf]");
    const toml::array& a = f.array(d, "[t0, tf], two numbers");
    if (a.size() != 2) throw ProblemError(doc_.pos(d), describe(d), "[t0, tf], two numbers");
    p_.time.t0 = f.number(*a.get(0), "a number t0");
    p_.time.tf = f.number(*a.get(1), "a number tf");
    p_.time.pos = doc_.pos(d);
    if (!(p_.time.t0 < p_.time.tf))
      throw ProblemError(doc_.pos(d), "t0 >= tf", "a time domain [t0, tf] with t0 < tf");
    const toml::node& dl = f.require("delta", "a slice width (number) or \"auto\"");
    if (dl.is_string()) {
      if (dl.as_string()->get() != "auto") throw ProblemError(doc_.pos(dl), describe(dl), "a number or \"auto\"");
    } else {
      const double v = f.number(dl, "a slice width (number > 0) or \"auto\"");
      if (!(v > 0) || v > p_.time.tf - p_.time.t0)
        throw ProblemError(doc_.pos(dl), "delta = " + doc_.raw(dl), "a slice width in (0, tf - t0]");
      if ((p_.time.tf - p_.time.t0) / v > 5e7)
        throw ProblemError(doc_.pos(dl), "delta = " + doc_.raw(dl) + " (more than 5e7 slices)", "a larger delta");
      p_.time.delta = v;
    }
  }

  // [time] points = {data, column}: the stamps of a table.
  void read_time_points(const Fields& f, const toml::node& pn) {
    for (const char* k : {"domain", "delta"})
      if (const toml::node* n = f.find(k))
        throw ProblemError(doc_.pos(*n), std::string("'") + k + "' with 'points'",
                           "either points = {data, column} or domain and delta");
    const Fields pf(doc_, f.table(pn, "a table {data = \"NAME\", column = \"t\"}"), "[time] points", {"data", "column"});
    const toml::node& dn = pf.require("data", "a [data.NAME] table");
    const DataSpec& d = data_table(pf, dn);
    const toml::node& cn = pf.require("column", "its time column");
    const std::string col = pf.string(cn, "a column name (string)");
    if (!d.table.has_column(col)) throw ProblemError(doc_.pos(cn), "the column '" + col + "' missing from table '" + d.name + "'", "a column of it");
    p_.time.points = d.table.values(col);
    p_.time.points_data = d.name;
    p_.time.pos = doc_.pos(pn);
    if (p_.time.points.size() < 2)
      throw ProblemError(doc_.pos(cn), std::to_string(p_.time.points.size()) + " time point(s)", "at least 2");
    for (std::size_t i = 1; i < p_.time.points.size(); ++i)
      if (!(p_.time.points[i] > p_.time.points[i - 1]))
        throw ProblemError(doc_.pos(cn), "the stamps of rows " + std::to_string(i - 1) + " and " + std::to_string(i) + " of '" +
                                             d.name + "' not increasing (" + number_text(p_.time.points[i - 1]) + ", " +
                                             number_text(p_.time.points[i]) + ")",
                           "strictly increasing time points");
    p_.time.t0 = p_.time.points.front();
    p_.time.tf = p_.time.points.back();
  }

  const DataSpec& data_table(const Fields& f, const toml::node& dn) {
    const std::string name = f.string(dn, "a data table name (string)");
    if (const DataSpec* d = p_.table(name)) return *d;
    std::string names;
    for (const DataSpec& x : p_.data) names += (names.empty() ? "" : ", ") + x.name;
    throw ProblemError(doc_.pos(dn), "the unknown table '" + name + "'", "a [data.NAME] table (" + names + ")");
  }

  // ---- [data.NAME] ----
  void read_data(const std::string& name, const toml::key& key, const toml::node& node) {
    const SourcePos kp = doc_.pos(key.source());
    if (!valid_name(name)) throw ProblemError(kp, "the table name '" + name + "'", "a name such as ranges or odo_1");
    const Fields f(doc_, Fields(doc_, toml::table{}, "", {}).table(node, "a table [data." + name + "]"),
                   "[data." + name + "]", {"file", "columns"});
    DataSpec d;
    d.name = name;
    d.pos = kp;
    const toml::node& fn = f.require("file", "a CSV path relative to the problem file");
    const std::string file = detail::expand_env(f.string(fn, "a CSV path (string)"), doc_.pos(fn));
    d.path = (base_ / file).lexically_normal().string();
    if (std::filesystem::is_directory(d.path))
      throw ProblemError(doc_.pos(fn), "the directory " + d.path, "a CSV file");
    try {
      d.table = CsvTable::read(d.path);
    } catch (const Error& e) {
      throw ProblemError(doc_.pos(fn), std::string("an unreadable CSV: ") + e.what(), "a numeric CSV with a header line");
    }
    if (const toml::node* cn = f.find("columns")) {
      for (const toml::node& c : f.array(*cn, "an array of column names")) {
        const std::string col = f.string(c, "a column name (string)");
        if (!d.table.has_column(col)) {
          std::string cols;
          for (const auto& h : d.table.columns()) cols += (cols.empty() ? "" : ", ") + h;
          throw ProblemError(doc_.pos(c), "the column '" + col + "' missing from " + d.path, "one of: " + cols);
        }
      }
    }
    p_.data.push_back(std::move(d));
  }

  // ---- [var.NAME] ----
  void check_bound(const BoundSpec& b, bool of_t) {
    if (b.expr.empty()) return;
    const std::vector<std::string> vars = of_t ? std::vector<std::string>{"t"} : std::vector<std::string>{};
    try {
      (void)detail::parse_expr(vars, b.expr);
    } catch (const ParseError& e) {
      throw ProblemError(b.pos, std::string("the bound \"") + b.expr + "\" (" + e.what() + ")",
                         of_t ? "an expression of t such as \"sin(t) + [-0.1, 0.1]\""
                              : "a constant expression such as \"[-1, 1]\" or \"pi/2 + [-0.01, 0.01]\"");
    }
  }

  std::vector<BoundSpec> read_bounds(const Fields& f, const toml::node& n, std::size_t dim, bool of_t) {
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

  void read_var(const std::string& name, const toml::key& key, const toml::node& node) {
    const SourcePos kp = doc_.pos(key.source());
    if (!valid_name(name))
      throw ProblemError(kp, "the variable name '" + name + "'",
                         "an identifier (letters, digits, _; not __, not a function name)");
    const Fields f(doc_, Fields(doc_, toml::table{}, "", {}).table(node, "a table [var." + name + "]"),
                   "[var." + name + "]", {"kind", "dim", "value", "at", "slices"});
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
        if (gs.t < p_.time.t0 || gs.t > p_.time.tf)
          throw ProblemError(doc_.pos(tn), "t = " + doc_.raw(tn) + " outside the time domain",
                             "a time in [" + number_text(p_.time.t0) + ", " + number_text(p_.time.tf) + "]");
        gs.value = read_bounds(gf, gf.require("value", "the bounds at t"), v.dim, false);
        v.at.push_back(std::move(gs));
      }
    }
    if (const toml::node* sn = f.find("slices")) v.slices = read_slices(f, *sn, v);
    if (p_.table(name)) throw ProblemError(kp, "the variable '" + name + "' named as a data table", "distinct names");
    p_.vars.push_back(std::move(v));
  }

  SliceDataSpec read_slices(const Fields& f, const toml::node& sn, const VarSpec& v) {
    if (v.kind != VarKind::Tube) throw ProblemError(doc_.pos(sn), "'slices' for the " + std::string(kind_name(v.kind)) + " '" + v.name + "'", "'slices' on a tube");
    if (p_.time.points.empty())
      throw ProblemError(doc_.pos(sn), "'slices' without time points from data", "[time] points = {data, column}");
    const Fields sf(doc_, f.table(sn, "a table {data = \"NAME\", value = \"expression\"}"), "the slices of " + v.name, {"data", "value"});
    SliceDataSpec s;
    const toml::node& dn = sf.require("data", "a [data.NAME] table, one row per slice");
    const DataSpec& d = data_table(sf, dn);
    s.data = d.name;
    if (d.table.nb_rows() + 1 != p_.time.points.size())
      throw ProblemError(doc_.pos(dn), "the table '" + d.name + "' of " + std::to_string(d.table.nb_rows()) + " rows",
                         "one row per slice: " + std::to_string(p_.time.points.size() - 1) + " rows");
    const toml::node& vn = sf.require("value", "an expression of the row's columns and dt");
    s.value = {sf.bound_text(vn), detail::shifted(doc_.pos(vn), vn.is_string() ? 1 : 0)};
    std::vector<std::string> names = d.table.columns();
    names.push_back("dt");
    try {
      (void)detail::parse_expr(names, s.value.expr);
    } catch (const ParseError& e) {
      throw ProblemError(s.value.pos, std::string("the value \"") + s.value.expr + "\" (" + e.what() + ")",
                         "an expression of the columns of '" + d.name + "' and dt");
    }
    return s;
  }

  // ---- [[constraint]] ----
  std::string known_vars() const {
    std::string s;
    for (const VarSpec& v : p_.vars)
      s += (s.empty() ? "" : ", ") + (v.dim > 1 || v.kind == VarKind::TubeVector || v.kind == VarKind::Box
                                          ? v.name + "[0.." + std::to_string(v.dim - 1) + "]"
                                          : v.name);
    return s;
  }

  const VarSpec& tube_var(const Fields& f, const char* key) {
    return tube_var(f, f.require(key, "the name of a tube variable"));
  }

  const VarSpec& tube_var(const Fields& f, const toml::node& n) {
    const std::string name = f.string(n, "the name of a tube variable (string)");
    const VarSpec* v = p_.var(name);
    if (!v || !v->is_tube())
      throw ProblemError(doc_.pos(n), v ? "the " + std::string(kind_name(v->kind)) + " '" + name + "'" : "'" + name + "'",
                         "a tube or tube_vector variable (" + known_vars() + ")");
    return *v;
  }

  void read_constraint(const Fields& top, const toml::node& node) {
    const std::size_t index = p_.constraints.size() + 1;
    const toml::table& t = top.table(node, "a [[constraint]] table");
    const toml::node* kn = t.get("kind");
    ConstraintSpec c;
    c.pos = doc_.pos(node);
    const std::string expected_kind =
        "kind = \"expr\", \"deriv\", \"second_deriv\", \"increment\", \"eval\", \"heading\" or \"heading_window\"";
    if (!kn) throw ProblemError(c.pos, "constraint " + std::to_string(index) + " without a kind", expected_kind);
    const std::string ks = top.string(*kn, expected_kind);
    const std::string where = "constraint " + std::to_string(index) + " (" + ks + ")";
    auto dims = [this](const std::string& n) -> std::optional<std::size_t> {
      const VarSpec* v = p_.var(n);
      return v ? std::optional<std::size_t>(v->dim) : std::nullopt;
    };
    auto is_vec = [this](const std::string& n) {
      const VarSpec* v = p_.var(n);
      return v && (v->kind == VarKind::TubeVector || v->kind == VarKind::Box);
    };
    if (ks == "expr") {
      const Fields f(doc_, t, where, {"kind", "expr"});
      c.kind = ConstraintKind::Expr;
      read_expr(f, c, dims, is_vec, known_vars());
      c.label = where + ": " + c.expr + " = 0";
    } else if (ks == "deriv" || ks == "increment" || ks == "second_deriv") {
      // x' = v, x(t_k+1) - x(t_k) in v(k), x'' in a: a tube of x's kind and dimension.
      const char* vkey = ks == "second_deriv" ? "a" : "v";
      const Fields f(doc_, t, where, {"kind", "x", vkey});
      c.kind = ks == "deriv" ? ConstraintKind::Deriv : ks == "increment" ? ConstraintKind::Increment : ConstraintKind::SecondDeriv;
      const VarSpec& x = tube_var(f, "x");
      const VarSpec& v = tube_var(f, vkey);
      if (x.dim != v.dim || x.kind != v.kind)
        throw ProblemError(doc_.pos(*f.find(vkey)),
                           "'" + v.name + "' (" + kind_name(v.kind) + ", dim " + std::to_string(v.dim) + ")",
                           "a variable of the kind and dimension of '" + x.name + "' (" + kind_name(x.kind) + ", dim " +
                               std::to_string(x.dim) + ")");
      c.x = x.name;
      c.v = v.name;
      c.label = where + ": " + (ks == "deriv"          ? c.x + "' = " + c.v
                                : ks == "second_deriv" ? c.x + "'' in " + c.v
                                                       : c.x + "(t_k+1) - " + c.x + "(t_k) in " + c.v + "(k)");
    } else if (ks == "heading") {
      const Fields f(doc_, t, where, {"kind", "p", "psi", "dist", "omega", "track"});
      c.kind = ConstraintKind::Heading;
      read_odometry(f, c, {std::pair{"psi", &c.psi}, std::pair{"dist", &c.dist}, std::pair{"omega", &c.omega}});
      c.label = where + ": " + c.p + " from " + c.dist + " along " + c.psi + " (track error " + c.track + ")";
    } else if (ks == "heading_window") {
      const Fields f(doc_, t, where, {"kind", "p", "psi", "dist", "dpsi", "omega", "track", "window", "turn_accel", "stride"});
      c.kind = ConstraintKind::HeadingWindow;
      read_odometry(f, c,
                    {std::pair{"psi", &c.psi}, std::pair{"dist", &c.dist}, std::pair{"dpsi", &c.dpsi}, std::pair{"omega", &c.omega}});
      const toml::node& wn = f.require("window", "the length of the windows (s, a number > 0)");
      c.window = f.number(wn, "the length of the windows (s, a number > 0)");
      if (!(c.window > 0)) throw ProblemError(doc_.pos(wn), "window = " + doc_.raw(wn), "a window length > 0 (s)");
      if (const toml::node* an = f.find("turn_accel")) {
        if (!(f.number(*an, "a turn acceleration bound > 0 (rad/s^2)") > 0))
          throw ProblemError(doc_.pos(*an), "turn_accel = " + doc_.raw(*an), "a turn acceleration bound > 0 (rad/s^2)");
        c.turn_accel = f.bound_text(*an);
      }
      if (const toml::node* sn = f.find("stride")) {
        const std::int64_t s = f.integer(*sn, "a window every `stride` slices (an integer >= 1)");
        if (s < 1) throw ProblemError(doc_.pos(*sn), "stride = " + doc_.raw(*sn), "an integer >= 1 (slices)");
        c.stride = static_cast<std::size_t>(s);
      }
      c.label = where + ": " + c.p + " over windows of " + doc_.raw(wn) + " s against " + c.psi + " and " + c.dpsi;
    } else if (ks == "eval") {
      read_eval(Fields(doc_, t, where, {"kind", "data", "y", "v", "time", "time_error", "errors", "where", "gates", "join", "expr"}), c, where);
    } else {
      throw ProblemError(doc_.pos(*kn), describe(*kn), expected_kind);
    }
    p_.constraints.push_back(std::move(c));
  }

  // The odometry of a planar vehicle (heading, heading_window): p a 2-D
  // tube_vector, the scalar tubes of `scalars`, and the track error.
  void read_odometry(const Fields& f, ConstraintSpec& c,
                     std::initializer_list<std::pair<const char*, std::string*>> scalars) {
    const VarSpec& p = tube_var(f, "p");
    if (p.kind != VarKind::TubeVector || p.dim != 2)
      throw ProblemError(doc_.pos(*f.find("p")), "'" + p.name + "' (" + kind_name(p.kind) + ", dim " + std::to_string(p.dim) + ")",
                         "a position: a tube_vector of dim 2");
    c.p = p.name;
    for (auto [key, out] : scalars) {
      const VarSpec& s = tube_var(f, key);
      if (s.kind != VarKind::Tube) throw ProblemError(doc_.pos(*f.find(key)), "the tube_vector '" + s.name + "'", "a scalar tube");
      *out = s.name;
    }
    if (const toml::node* tr = f.find("track")) {
      if (!(f.number(*tr, "a track error >= 0 (rad)") >= 0)) throw ProblemError(doc_.pos(*tr), "a negative track error", "a track error >= 0");
      c.track = f.bound_text(*tr);
    }
  }

  template <class Dims, class Vec>
  void read_expr(const Fields& f, ConstraintSpec& c, const Dims& dims, const Vec& vec, const std::string& known) {
    const toml::node& e = f.require("expr", "an expression such as \"v[0] - 10*cos(x[2])\" (= 0)");
    c.expr = f.string(e, "an expression (string)");
    c.expr_pos = shifted(doc_.pos(e), 1);
    (void)rewrite_refs(c.expr, c.expr_pos, dims, vec, known);
  }

  // A string or an array of strings (at least one).
  std::vector<const toml::node*> one_or_many(const Fields& f, const toml::node& n, const std::string& expected) {
    std::vector<const toml::node*> out;
    if (n.is_array()) {
      for (const toml::node& e : f.array(n, expected)) out.push_back(&e);
      if (out.empty()) throw ProblemError(doc_.pos(n), "an empty array", expected);
    } else {
      out.push_back(&n);
    }
    return out;
  }

  void read_eval(const Fields& f, ConstraintSpec& c, const std::string& where) {
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
      if (!d->table.has_column(col)) {
        std::string cols;
        for (const auto& h : d->table.columns()) cols += (cols.empty() ? "" : ", ") + h;
        throw ProblemError(doc_.pos(n), "the column '" + col + "' missing from table '" + c.data + "'", "one of: " + cols);
      }
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
        if (!d->table.has_column(std::string(key.str())))
          throw ProblemError(doc_.pos(key.source()), "the column '" + std::string(key.str()) + "' missing from table '" +
                                                         c.data + "'", "a column of it");
        if (f.number(node, "an error >= 0 (number)") < 0)
          throw ProblemError(doc_.pos(node), "a negative error", "an error >= 0");
        c.errors[std::string(key.str())] = f.bound_text(node);
      }
    }
    if (const toml::node* wn = f.find("where")) {
      for (auto&& [key, node] : f.table(*wn, "a table {column = value}")) {
        if (!d->table.has_column(std::string(key.str())))
          throw ProblemError(doc_.pos(key.source()), "the column '" + std::string(key.str()) + "' missing from table '" +
                                                         c.data + "'", "a column of it");
        c.where[std::string(key.str())] = f.number(node, "a value of the column (number)");
      }
    }
    if (const toml::node* g = f.find("gates")) {
      if (!g->is_boolean()) throw ProblemError(doc_.pos(*g), describe(*g), "true or false");
      c.gates = g->as_boolean()->get();
    }
    const DataSpec* joined = nullptr;
    if (const toml::node* jn = f.find("join")) {
      const Fields jf(doc_, f.table(*jn, "a table {data = \"NAME\", on = \"column\"}"), where + " join", {"data", "on"});
      joined = &data_table(jf, jf.require("data", "a [data.NAME] table"));
      const toml::node& on = jf.require("on", "a column of both tables");
      c.join_on = jf.string(on, "a column name (string)");
      c.join_data = joined->name;
      if (!d->table.has_column(c.join_on) || !joined->table.has_column(c.join_on))
        throw ProblemError(doc_.pos(on), "the column '" + c.join_on + "'", "a column of both '" + c.data + "' and '" + joined->name + "'");
      for (const auto& col : joined->table.columns())
        if (col != c.join_on && d->table.has_column(col))
          throw ProblemError(doc_.pos(*jn), "the column '" + col + "' in both tables", "distinct column names besides '" + c.join_on + "'");
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
      if (has_column(n)) return 1;
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
    known += "the columns of '" + c.data + "'" + (joined ? " and '" + joined->name + "'" : "");
    for (const VarSpec& v : p_.vars)
      if (!v.is_tube()) known += ", " + v.name;
    read_expr(f, c, dims, vec, known);
    std::vector<std::string> cols = d->table.columns();
    if (joined) cols.insert(cols.end(), joined->table.columns().begin(), joined->table.columns().end());
    for (const auto& col : cols)
      if (p_.var(col) && !y_of(col))
        throw ProblemError(c.pos, "the column '" + col + "' named as a variable", "distinct names in an eval observation");
    c.label = where + ": " + c.expr + " = 0 at " + names + "(" +
              (c.time_columns.empty() ? std::string("t unknown") : c.time_columns[0]) + ") for every row of '" +
              c.data + "'" + (c.where.empty() ? "" : " kept by 'where'");
  }

  void read_loops(const Fields& f, const toml::node& ln) {
    const Fields lf(doc_, f.table(ln, "a table {v = \"velocity\", p = \"position\", eps = width}"), "[output] loops",
                    {"v", "p", "eps"});
    LoopsSpec l;
    l.pos = doc_.pos(ln);
    for (auto [key, out] : {std::pair{"v", &l.v}, std::pair{"p", &l.p}}) {
      const toml::node* n = lf.find(key);
      if (!n) {
        if (std::string(key) == "v") lf.require("v", "the velocity, a tube_vector of dim 2");
        continue;
      }
      const VarSpec& v = tube_var(lf, *n);
      if (v.kind != VarKind::TubeVector || v.dim != 2)
        throw ProblemError(doc_.pos(*n), "'" + v.name + "' (" + kind_name(v.kind) + ", dim " + std::to_string(v.dim) + ")",
                           "a tube_vector of dim 2");
      *out = v.name;
    }
    if (const toml::node* e = lf.find("eps")) {
      const double eps = lf.number(*e, "a paving width > 0 (time units)");
      if (!(eps > 0) || (p_.time.tf - p_.time.t0) / eps > 1e6)
        throw ProblemError(doc_.pos(*e), "eps = " + doc_.raw(*e), "a paving width in (0, tf - t0], at least (tf - t0)/1e6");
      l.eps = eps;
    }
    p_.output.loops = l;
  }

  // ---- [network] ----
  void read_network(const toml::table& t) {
    const Fields f(doc_, t, "[network]", {"ratio", "order"});
    if (const toml::node* o = f.find("order")) {
      const std::string os = f.string(*o, "\"file\" or \"cost\"");
      if (os == "cost") p_.network.order = ConstraintOrder::Cost;
      else if (os != "file") throw ProblemError(doc_.pos(*o), describe(*o), "\"file\" or \"cost\"");
    }
    p_.network.pos = f.pos();
    if (const toml::node* r = f.find("ratio")) {
      const double v = f.number(*r, "a ratio in [0, 1)");
      if (!(v >= 0 && v < 1)) throw ProblemError(doc_.pos(*r), "ratio = " + doc_.raw(*r), "a ratio in [0, 1)");
      p_.network.ratio = v;
    }
  }

  // ---- [output] ----
  std::pair<std::string, std::size_t> tube_ref(const Fields& f, const toml::node& n, bool allow_whole) {
    const std::string s = f.string(n, "a tube such as \"x\" or \"x[0]\"");
    const auto b = s.find('[');
    const std::string name = s.substr(0, b);
    const VarSpec* v = p_.var(name);
    if (!v || !v->is_tube()) throw ProblemError(doc_.pos(n), "'" + s + "'", "a tube variable (" + known_vars() + ")");
    if (b == std::string::npos) {
      if (!allow_whole && v->kind == VarKind::TubeVector)
        throw ProblemError(doc_.pos(n), "'" + s + "'", "a component such as " + name + "[0]");
      return {name, static_cast<std::size_t>(-1)};
    }
    std::size_t i = 0;
    bool ok = s.back() == ']' && s.size() > b + 2 && s.size() < b + 8;
    for (std::size_t k = b + 1; ok && k + 1 < s.size(); ++k) {
      ok = std::isdigit(static_cast<unsigned char>(s[k]));
      i = i * 10 + static_cast<std::size_t>(s[k] - '0');
    }
    if (!ok || v->kind != VarKind::TubeVector || i >= v->dim)
      throw ProblemError(doc_.pos(n), "'" + s + "'",
                         "a component " + name + "[i] with i from 0 to " + std::to_string(v->dim - 1) +
                             (v->kind == VarKind::TubeVector ? "" : " (a scalar tube has none: write " + name + ")"));
    return {name, i};
  }

  void read_output(const toml::table& t) {
    const Fields f(doc_, t, "[output]", {"times", "plots", "maps", "truth", "landmarks", "loops"});
    if (const toml::node* ln = f.find("loops")) read_loops(f, *ln);
    if (const toml::node* ln = f.find("landmarks")) {
      const Fields lf(doc_, f.table(*ln, "a table {data = \"NAME\", columns = [\"x\", \"y\"]}"), "[output] landmarks",
                      {"data", "columns"});
      LandmarksSpec l;
      l.pos = doc_.pos(*ln);
      const DataSpec& d = data_table(lf, lf.require("data", "a [data.NAME] table"));
      l.data = d.name;
      const toml::node& cn = lf.require("columns", "two columns [\"x\", \"y\"]");
      const toml::array& a = lf.array(cn, "two columns [\"x\", \"y\"]");
      if (a.size() != 2) throw ProblemError(doc_.pos(cn), describe(cn), "two columns [\"x\", \"y\"]");
      for (const toml::node& c : a) {
        const std::string col = lf.string(c, "a column name");
        if (!d.table.has_column(col))
          throw ProblemError(doc_.pos(c), "the column '" + col + "' missing from table '" + d.name + "'", "a column of it");
      }
      l.x = a.get(0)->as_string()->get();
      l.y = a.get(1)->as_string()->get();
      p_.output.landmarks = l;
    }
    if (const toml::node* ts = f.find("times"))
      for (const toml::node& n : f.array(*ts, "an array of times")) {
        const double v = f.number(n, "a time (number)");
        if (v < p_.time.t0 || v > p_.time.tf)
          throw ProblemError(doc_.pos(n), "the time " + doc_.raw(n) + " outside the domain",
                             "a time in [" + number_text(p_.time.t0) + ", " + number_text(p_.time.tf) + "]");
        p_.output.times.push_back(v);
      }
    if (const toml::node* ps = f.find("plots"))
      for (const toml::node& n : f.array(*ps, "an array of tubes such as [\"x\", \"v[1]\"]"))
        p_.output.plot_tubes.push_back(tube_ref(f, n, true));
    if (const toml::node* ms = f.find("maps"))
      for (const toml::node& n : f.array(*ms, "an array of pairs such as [[\"x[0]\", \"x[1]\"]]")) {
        const toml::array& a = f.array(n, "a pair [\"x[0]\", \"x[1]\"]");
        if (a.size() != 2) throw ProblemError(doc_.pos(n), describe(n), "a pair [\"x[0]\", \"x[1]\"]");
        const auto i = tube_ref(f, *a.get(0), false), j = tube_ref(f, *a.get(1), false);
        if (i.first != j.first || p_.var(i.first)->kind != VarKind::TubeVector)
          throw ProblemError(doc_.pos(n), "components of different variables", "two components of one tube_vector");
        p_.output.maps.push_back({i.first, {i.second, j.second}});
      }
    if (const toml::node* tr = f.find("truth")) {
      const Fields tf(doc_, f.table(*tr, "a table {data, time, columns}"), "[output.truth]", {"data", "time", "columns"});
      TruthSpec ts;
      ts.pos = doc_.pos(*tr);
      const toml::node& dn = tf.require("data", "a [data.NAME] table");
      ts.data = tf.string(dn, "a data table name");
      const DataSpec* d = p_.table(ts.data);
      if (!d) throw ProblemError(doc_.pos(dn), "the unknown table '" + ts.data + "'", "a [data.NAME] table");
      auto col = [&](const toml::node& n) {
        const std::string c = tf.string(n, "a column name");
        if (!d->table.has_column(c))
          throw ProblemError(doc_.pos(n), "the column '" + c + "' missing from table '" + ts.data + "'", "a column of it");
        return c;
      };
      ts.time_column = col(tf.require("time", "the time column"));
      for (auto&& [key, node] : tf.table(tf.require("columns", "{var = [columns]}"), "a table {var = [columns]}")) {
        const std::string name(key.str());
        const VarSpec* v = p_.var(name);
        if (!v || !v->is_tube())
          throw ProblemError(doc_.pos(key.source()), "'" + name + "'", "a tube variable (" + known_vars() + ")");
        std::vector<std::string> cols;
        if (node.is_string()) cols.push_back(col(node));
        else
          for (const toml::node& c : tf.array(node, "a column name or an array of them")) cols.push_back(col(c));
        if (cols.size() != v->dim)
          throw ProblemError(doc_.pos(node), std::to_string(cols.size()) + " column(s)",
                             std::to_string(v->dim) + " (one per component of '" + name + "')");
        ts.columns[name] = cols;
      }
      p_.output.truth = ts;
    }
  }

  Problem p_;
  Document doc_;
  std::filesystem::path base_;
};

}  // namespace

Problem parse_problem(const std::string& text, const std::string& path) { return Loader(text, path).run(); }

Problem load_problem(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw ProblemError(SourcePos{path}, "a directory", "a problem file (TOML)");
  std::ifstream is(path, std::ios::binary);
  if (!is) throw ProblemError(SourcePos{path}, "a file that cannot be read", "a readable problem file (TOML)");
  std::ostringstream ss;
  ss << is.rdbuf();
  return parse_problem(ss.str(), path);
}

}  // namespace sillage
