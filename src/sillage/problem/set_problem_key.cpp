#include "sillage/problem/set_problem_key.h"

#include <cstddef>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "sillage/problem/problem_error.h"

namespace sillage {

namespace {

// One step of a key: a name, or an element of an array.
struct KeyStep {
  std::string name;
  std::size_t index = 0;
  bool is_index = false;
};

std::vector<KeyStep> key_steps(const std::string& key, const std::string& file) {
  const auto bad = [&](const std::string& why) {
    return ProblemError(SourcePos{file}, "the key \"" + key + "\" (" + why + ")",
                        "names joined by dots, [i] for an element of an array, e.g. \"constraint[8].time_error\"");
  };
  std::vector<KeyStep> steps;
  std::size_t i = 0;
  while (i < key.size()) {
    if (key[i] == '[') {
      const std::size_t close = key.find(']', i);
      if (close == std::string::npos) throw bad("an unclosed [");
      const std::string digits = key.substr(i + 1, close - i - 1);
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9)
        throw bad("the index [" + digits + "] is not a whole number");
      steps.push_back({"", std::stoul(digits), true});
      i = close + 1;
      if (i < key.size() && key[i] == '.') ++i;
      continue;
    }
    const std::size_t end = key.find_first_of(".[", i);
    const std::string name = key.substr(i, end == std::string::npos ? std::string::npos : end - i);
    if (name.empty()) throw bad("an empty name");
    steps.push_back({name, 0, false});
    i = end == std::string::npos ? key.size() : end;
    if (i < key.size() && key[i] == '.') {
      ++i;
      if (i == key.size()) throw bad("a dot at its end");
    }
  }
  if (steps.empty()) throw bad("empty");
  return steps;
}

std::string keys_of(const toml::table& t) {
  std::string s;
  for (const auto& [k, v] : t) s += (s.empty() ? "" : ", ") + std::string(k.str());
  return s.empty() ? "none" : s;
}

// The node of key in the tree; ProblemError naming what is there instead.
const toml::node& find_key(const toml::table& root, const std::vector<KeyStep>& steps, const std::string& key,
                           const std::string& file) {
  const toml::node* n = &root;
  std::string where = "the file";
  for (const KeyStep& s : steps) {
    if (s.is_index) {
      const toml::array* a = n->as_array();
      if (!a) throw ProblemError(SourcePos{file}, "the key \"" + key + "\": " + where + " is not an array",
                                 "an index [i] only after an array");
      if (s.index >= a->size())
        throw ProblemError(SourcePos{file}, "the key \"" + key + "\": " + where + " has " +
                                                std::to_string(a->size()) + " element(s)",
                           "an index from 0 to " + std::to_string(a->size()) + " - 1");
      n = a->get(s.index);
      where += "[" + std::to_string(s.index) + "]";
      continue;
    }
    const toml::table* t = n->as_table();
    if (!t) throw ProblemError(SourcePos{file}, "the key \"" + key + "\": " + where + " is not a table",
                               "a name only after a table");
    n = t->get(s.name);
    if (!n) throw ProblemError(SourcePos{file}, "the key \"" + key + "\": no '" + s.name + "' in " + where +
                                                    " (its keys: " + keys_of(*t) + ")",
                               "a key the file states (a swept key replaces a value, it adds none)");
    where = where == "the file" ? s.name : where + "." + s.name;
  }
  return *n;
}

// The offset in text of a 1-based line and column (columns count bytes, as Document::raw).
std::size_t offset_of(std::string_view text, const toml::source_position& p) {
  std::size_t off = 0;
  for (std::size_t line = 1; line < p.line; ++line) {
    const std::size_t nl = text.find('\n', off);
    if (nl == std::string_view::npos) return text.size();
    off = nl + 1;
  }
  return std::min(text.size(), off + p.column - 1);
}

}  // namespace

std::string set_problem_key(const std::string& text, const std::string& file, const std::string& key,
                            const std::string& value) {
  const std::vector<KeyStep> steps = key_steps(key, file);
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw ProblemError(SourcePos{file, static_cast<int>(b.line), static_cast<int>(b.column)},
                       std::string(e.description()), "a TOML file");
  }
  // One value on one line: a newline could add keys after it, and would move the lines below.
  bool one_value = value.find_first_of("\r\n") == std::string::npos;
  try {
    one_value = one_value && toml::parse("v = " + value).size() == 1;
  } catch (const toml::parse_error&) {
    one_value = false;
  }
  if (!one_value)
    throw ProblemError(SourcePos{file}, "the value '" + value + "' for \"" + key + "\"",
                       "one TOML value on one line, as written in the file (a number, \"text\" in quotes, an "
                       "array [a, b])");
  const toml::node& n = find_key(root, steps, key, file);
  const toml::source_region& r = n.source();
  if (n.is_table() && !n.as_table()->is_inline())
    throw ProblemError(SourcePos{file, static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)},
                       "the key \"" + key + "\", a whole table", "a key with a value");
  if (n.is_array_of_tables() && !n.as_array()->empty() && !n.as_array()->get(0)->as_table()->is_inline())
    throw ProblemError(SourcePos{file}, "the key \"" + key + "\", an array of tables [[...]]", "a key with a value");
  const std::size_t b = offset_of(text, r.begin), e = offset_of(text, r.end);
  return text.substr(0, b) + value + text.substr(e);
}

}  // namespace sillage
