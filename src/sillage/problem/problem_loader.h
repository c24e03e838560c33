#pragma once
// ProblemLoader: reads the TOML tree of a problem file into a Problem
// (load_problem.h), one table kind per source file: load_time.cpp,
// load_data.cpp, load_var.cpp, load_constraint.cpp (dispatch and "expr"),
// load_deriv.cpp, load_heading.cpp, load_eval.cpp, load_p_implies_z.cpp, load_output.cpp,
// load_loops.cpp, load_network.cpp; the look-ups they share (tables, tube
// variables, expressions) in load_lookup.cpp. Every error a ProblemError at
// the node's file:line:column.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sillage/problem/problem.h"
#include "sillage/problem/toml_fields.h"

namespace sillage::detail {

// A table, variable or column name: an identifier, no "__", not a function name.
bool valid_name(const std::string& s);

// "t, b, r": a table's columns, for messages (load_lookup.cpp).
std::string column_list(const CsvTable& table);
// The error for a column the table `name` does not have: its columns listed (load_lookup.cpp).
ProblemError missing_column(const SourcePos& pos, const std::string& column, const std::string& name, const CsvTable& table);
// ", at most 3 wrong in any 60 s": an eval's outliers as its label says them ("" without q).
std::string outliers_text(const ConstraintSpec& c);
// A column the problem reads: the table `name` has it and its cells are all
// finite numbers; a ProblemError at pos otherwise (load_lookup.cpp).
void require_column(const SourcePos& pos, const std::string& column, const std::string& name, const CsvTable& table);

// The values of a time column of table d strictly increasing: a ProblemError
// at pos naming the first two that are not, by line (load_lookup.cpp).
void require_increasing(const SourcePos& pos, const std::vector<double>& stamps, const DataSpec& d,
                        const std::string& expected);

class ProblemLoader {
 public:
  // text: the file's content; path names it in messages and is the base of the data paths.
  ProblemLoader(const std::string& text, const std::string& path);
  Problem run();

 private:
  using DimOf = std::function<std::optional<std::size_t>(const std::string&)>;
  using IsVector = std::function<bool(const std::string&)>;
  using TubeKeys = std::initializer_list<std::pair<const char*, std::string*>>;

  // [time] (load_time.cpp)
  void read_time(const toml::table& t);
  void read_time_points(const Fields& f, const toml::node& pn);
  // [data.NAME] (load_data.cpp)
  void read_data(const std::string& name, const toml::key& key, const toml::node& node);
  // [var.NAME] (load_var.cpp)
  void check_bound(const BoundSpec& b, bool of_t);
  std::vector<BoundSpec> read_bounds(const Fields& f, const toml::node& n, std::size_t dim, bool of_t);
  void read_var(const std::string& name, const toml::key& key, const toml::node& node);
  SliceDataSpec read_from_table(const Fields& f, const toml::node& sn, const VarSpec& v, bool gates);
  // [[constraint]], one reader per kind
  void read_constraint(const Fields& top, const toml::node& node);       // load_constraint.cpp
  void read_expr_constraint(const Fields& f, ConstraintSpec& c);          // load_constraint.cpp
  void read_deriv(const Fields& f, ConstraintSpec& c, const std::string& kind, const char* vkey);  // load_deriv.cpp
  void read_heading(const Fields& f, ConstraintSpec& c);                  // load_heading.cpp
  void read_heading_window(const Fields& f, ConstraintSpec& c);           // load_heading.cpp
  void read_odometry(const Fields& f, ConstraintSpec& c, TubeKeys scalars);  // load_heading.cpp
  void read_eval(const Fields& f, ConstraintSpec& c, const std::string& where);  // load_eval.cpp
  void read_p_implies_z(const Fields& f, ConstraintSpec& c);  // load_p_implies_z.cpp
  void read_python(const Fields& f, ConstraintSpec& c);       // load_python.cpp
  // [output] (load_output.cpp, load_loops.cpp)
  std::pair<std::string, std::size_t> tube_ref(const Fields& f, const toml::node& n, bool allow_whole);
  void read_output(const toml::table& t);
  void read_loops(const Fields& f, const toml::node& ln);
  // [network] (load_network.cpp)
  void read_network(const toml::table& t);
  void read_online(const toml::table& t);
  void read_outliers(const Fields& f, ConstraintSpec& c);
  // Shared look-ups (load_lookup.cpp)
  const DataSpec& data_table(const Fields& f, const toml::node& dn);
  // "v, x[0..2]": the variables, for messages; only the tube ones if tubes_only.
  std::string known_vars(bool tubes_only = false) const;
  const VarSpec& tube_var(const Fields& f, const char* key);
  const VarSpec& tube_var(const Fields& f, const toml::node& n);
  void read_expr(const Fields& f, ConstraintSpec& c, const DimOf& dims, const IsVector& vec, const std::string& known);
  std::vector<const toml::node*> one_or_many(const Fields& f, const toml::node& n, const std::string& expected);

  Problem p_;
  Document doc_;
  std::filesystem::path base_;
};

}  // namespace sillage::detail
