// The look-ups every table of a problem file shares: tables, tube variables, expressions.
#include "sillage/problem/problem_loader.h"

#include <cctype>
#include "sillage/expr/parser.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/problem/var_refs.h"

namespace sillage::detail {

bool valid_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return s.find("__") == std::string::npos && !detail::is_reserved_name(s);
}

std::string column_list(const CsvTable& table) {
  std::string cols;
  for (const auto& h : table.columns()) cols += (cols.empty() ? "" : ", ") + h;
  return cols;
}

ProblemError missing_column(const SourcePos& pos, const std::string& column, const std::string& name, const CsvTable& table) {
  return ProblemError(pos, "the column '" + column + "' missing from table '" + name + "'",
                      "one of its columns: " + column_list(table));
}

void require_column(const SourcePos& pos, const std::string& column, const std::string& name, const CsvTable& table) {
  if (!table.has_column(column)) throw missing_column(pos, column, name, table);
  try {
    (void)table.column(column);
  } catch (const ParseError& e) {  // a text column: a label, a missing value
    throw ProblemError(pos, "the column '" + column + "' of table '" + name + "', which is not all numbers (" + e.what() + ")",
                       "a column of finite numbers");
  }
}

const DataSpec& ProblemLoader::data_table(const Fields& f, const toml::node& dn) {
  const std::string name = f.string(dn, "a data table name (string)");
  if (const DataSpec* d = p_.table(name)) return *d;
  std::string names;
  for (const DataSpec& x : p_.data) names += (names.empty() ? "" : ", ") + x.name;
  throw ProblemError(doc_.pos(dn), "the unknown table '" + name + "'", "a [data.NAME] table (" + names + ")");
}

std::string ProblemLoader::known_vars(bool tubes_only) const {
  std::string s;
  for (const VarSpec& v : p_.vars) {
    if (tubes_only && !v.is_tube()) continue;
    const bool vector = v.dim > 1 || v.kind == VarKind::TubeVector || v.kind == VarKind::Box;
    s += (s.empty() ? "" : ", ") + (vector ? v.name + "[0.." + std::to_string(v.dim - 1) + "]" : v.name);
  }
  return s;
}

const VarSpec& ProblemLoader::tube_var(const Fields& f, const char* key) {
  return tube_var(f, f.require(key, "the name of a tube variable"));
}

const VarSpec& ProblemLoader::tube_var(const Fields& f, const toml::node& n) {
  const std::string name = f.string(n, "the name of a tube variable (string)");
  const VarSpec* v = p_.var(name);
  if (!v || !v->is_tube())
    throw ProblemError(doc_.pos(n), v ? "the " + std::string(kind_name(v->kind)) + " '" + name + "'" : "'" + name + "'",
                       "a tube or tube_vector variable (" + known_vars(true) + ")");
  return *v;
}

void ProblemLoader::read_expr(const Fields& f, ConstraintSpec& c, const DimOf& dims, const IsVector& vec, const std::string& known) {
  const toml::node& e = f.require("expr", "an expression such as \"v[0] - 10*cos(x[2])\" (= 0)");
  c.expr = f.string(e, "an expression (string)");
  c.expr_pos = shifted(doc_.pos(e), 1);
  (void)rewrite_refs(c.expr, c.expr_pos, dims, vec, known);
}

// A string or an array of strings (at least one).
std::vector<const toml::node*> ProblemLoader::one_or_many(const Fields& f, const toml::node& n, const std::string& expected) {
  std::vector<const toml::node*> out;
  if (n.is_array()) {
    for (const toml::node& e : f.array(n, expected)) out.push_back(&e);
    if (out.empty()) throw ProblemError(doc_.pos(n), "an empty array", expected);
  } else {
    out.push_back(&n);
  }
  return out;
}

void require_increasing(const SourcePos& pos, const std::vector<double>& stamps, const DataSpec& d,
                        const std::string& expected) {
  for (std::size_t i = 1; i < stamps.size(); ++i)
    if (!(stamps[i] > stamps[i - 1]))
      throw ProblemError(pos, "the stamps " + cell_text(stamps[i - 1]) + " at " + d.table.where(i - 1) + " and " +
                                  cell_text(stamps[i]) + " at line " + std::to_string(d.table.line(i)) + " of '" +
                                  d.name + "', not increasing",
                         expected);
}

}  // namespace sillage::detail
