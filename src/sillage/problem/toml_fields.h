#pragma once
// Typed access to the TOML tree of a problem file, every failure a
// ProblemError at the node's file:line:column (internal to load_problem).
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "sillage/problem/problem_error.h"

namespace sillage::detail {

// The file name and its lines, to quote numbers exactly as written.
struct Document {
  std::string file;
  std::vector<std::string> lines;
  SourcePos pos(const toml::source_region& r) const;
  SourcePos pos(const toml::node& n) const { return pos(n.source()); }
  // The characters of a one-line node as written ("0.1", not 0.1000000000000000055).
  std::string raw(const toml::node& n) const;
};

// A path with ${NAME} or ${NAME:-default} replaced by the environment
// variable NAME (or the default when NAME is unset or empty), so a problem
// can name a data folder that lives outside the repository. ProblemError at
// pos for an unset variable without a default or an unclosed ${.
std::string expand_env(const std::string& path, const SourcePos& pos);

// "a string \"abc\"", "an integer 3", "an array of 2 elements", "a table".
std::string describe(const toml::node& n);

// One table of the file, named `where` ("[time]", "[var.x]", "constraint 2").
class Fields {
 public:
  // ProblemError at the first key not in `allowed`.
  Fields(const Document& doc, const toml::table& table, std::string where, std::initializer_list<const char*> allowed);
  const toml::node* find(const char* key) const;
  const toml::node& require(const char* key, const std::string& expected) const;
  SourcePos pos() const { return doc_.pos(table_); }
  const std::string& where() const { return where_; }

  std::string string(const toml::node& n, const std::string& expected) const;
  double number(const toml::node& n, const std::string& expected) const;  // integer or float, finite
  std::int64_t integer(const toml::node& n, const std::string& expected) const;
  const toml::array& array(const toml::node& n, const std::string& expected) const;
  const toml::table& table(const toml::node& n, const std::string& expected) const;
  // A rigorous bound: a string expression, or a number as written.
  std::string bound_text(const toml::node& n) const;
  // The decimal as written, enclosed: [d, d] when the double read is the
  // number itself (0, 2.5, 1e3), else the two doubles around it (0.1): a
  // time written in the file is the decimal, not its nearest double.
  std::pair<double, double> number_as_written(const toml::node& n, const std::string& expected) const;

 private:
  const Document& doc_;
  const toml::table& table_;
  std::string where_;
};

}  // namespace sillage::detail
