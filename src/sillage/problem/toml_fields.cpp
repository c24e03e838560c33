#include "sillage/problem/toml_fields.h"

#include <cfenv>
#include <cmath>
#include <cstdlib>

#include "sillage/interval/rounding.h"

namespace sillage::detail {

SourcePos Document::pos(const toml::source_region& r) const {
  return SourcePos{file, static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)};
}

std::string Document::raw(const toml::node& n) const {
  const auto& r = n.source();
  if (r.begin.line == 0 || r.begin.line != r.end.line || r.begin.line > lines.size()) return "";
  const std::string& l = lines[r.begin.line - 1];
  const std::size_t b = r.begin.column - 1, e = std::min<std::size_t>(r.end.column - 1, l.size());
  return b < e ? l.substr(b, e - b) : "";
}

std::string describe(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: {
      std::string s = n.as_string()->get();
      if (s.size() > 40) s = s.substr(0, 37) + "...";
      return "a string \"" + s + "\"";
    }
    case toml::node_type::integer: return "an integer " + std::to_string(n.as_integer()->get());
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return n.as_boolean()->get() ? "the boolean true" : "the boolean false";
    case toml::node_type::array: return "an array of " + std::to_string(n.as_array()->size()) + " element(s)";
    case toml::node_type::table: return "a table";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time of day";
    case toml::node_type::date_time: return "a date-time";
    default: return "a value";
  }
}

Fields::Fields(const Document& doc, const toml::table& table, std::string where,
               std::initializer_list<const char*> allowed)
    : doc_(doc), table_(table), where_(std::move(where)) {
  std::string list;
  for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
  for (auto&& [key, node] : table) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || key.str() == a;
    if (!ok)
      throw ProblemError(doc.pos(key.source()), "the unknown key '" + std::string(key.str()) + "' in " + where_,
                         "one of: " + list);
  }
}

const toml::node* Fields::find(const char* key) const { return table_.get(key); }

const toml::node& Fields::require(const char* key, const std::string& expected) const {
  const toml::node* n = find(key);
  if (!n) throw ProblemError(pos(), "no key '" + std::string(key) + "' in " + where_, "'" + std::string(key) + "' = " + expected);
  return *n;
}

std::string Fields::string(const toml::node& n, const std::string& expected) const {
  if (!n.is_string()) throw ProblemError(doc_.pos(n), describe(n), expected);
  return n.as_string()->get();
}

double Fields::number(const toml::node& n, const std::string& expected) const {
  double v = 0;
  if (n.is_integer()) v = static_cast<double>(n.as_integer()->get());
  else if (n.is_floating_point()) v = n.as_floating_point()->get();
  else throw ProblemError(doc_.pos(n), describe(n), expected);
  if (!std::isfinite(v)) throw ProblemError(doc_.pos(n), "a number that is not finite", expected);
  return v;
}

std::int64_t Fields::integer(const toml::node& n, const std::string& expected) const {
  if (!n.is_integer()) throw ProblemError(doc_.pos(n), describe(n), expected);
  return n.as_integer()->get();
}

const toml::array& Fields::array(const toml::node& n, const std::string& expected) const {
  if (!n.is_array()) throw ProblemError(doc_.pos(n), describe(n), expected);
  return *n.as_array();
}

const toml::table& Fields::table(const toml::node& n, const std::string& expected) const {
  if (!n.is_table()) throw ProblemError(doc_.pos(n), describe(n), expected);
  return *n.as_table();
}

std::string Fields::bound_text(const toml::node& n) const {
  const std::string expected = "a bound: an expression string such as \"[-1, 1]\" or \"2*t + [-0.1, 0.1]\", or a number";
  if (n.is_string()) return n.as_string()->get();
  if (n.is_integer() || n.is_floating_point()) {
    (void)number(n, expected);
    const std::string raw = doc_.raw(n);
    if (raw.empty()) throw ProblemError(doc_.pos(n), "a number written over several lines", expected);
    return raw;
  }
  throw ProblemError(doc_.pos(n), describe(n), expected);
}

std::pair<double, double> Fields::number_as_written(const toml::node& n, const std::string& expected) const {
  const double d = number(n, expected);
  if (n.is_integer()) {  // exact unless beyond 2^53: compared in long double, 64 bits of mantissa
    if (static_cast<long double>(d) == static_cast<long double>(n.as_integer()->get())) return {d, d};
    return {rounding::next_down(d), rounding::next_up(d)};
  }
  std::string text;
  for (char c : bound_text(n))
    if (c != '_') text += c;  // TOML's digit separators
  // strtod rounds in the current mode (glibc): down and up give the doubles
  // around the decimal, equal when it is one.
  const int mode = std::fegetround();
  std::fesetround(FE_DOWNWARD);
  const double lo = std::strtod(text.c_str(), nullptr);
  std::fesetround(FE_UPWARD);
  const double hi = std::strtod(text.c_str(), nullptr);
  std::fesetround(mode);
  if (!(lo <= d && d <= hi)) return {rounding::next_down(d), rounding::next_up(d)};  // a form strtod reads otherwise
  return {lo, hi};
}

std::string expand_env(const std::string& path, const SourcePos& pos) {
  std::string out;
  for (std::size_t i = 0; i < path.size();) {
    if (path.compare(i, 2, "${") != 0) {
      out += path[i++];
      continue;
    }
    const std::size_t end = path.find('}', i);
    if (end == std::string::npos) throw ProblemError(pos, "an unclosed ${ in \"" + path + "\"", "${NAME} or ${NAME:-default}");
    const std::string inner = path.substr(i + 2, end - i - 2);
    const std::size_t sep = inner.find(":-");
    const std::string name = inner.substr(0, sep);
    const char* value = std::getenv(name.c_str());
    if (value && *value) out += value;
    else if (sep != std::string::npos) out += inner.substr(sep + 2);
    else throw ProblemError(pos, "the environment variable " + name + " unset", "it set, or a default: ${" + name + ":-path}");
    i = end + 1;
  }
  return out;
}

}  // namespace sillage::detail
