// [[constraint]] kind = "python": a user's contractor written in Python (a
// sillage.TubeCtc subclass) on tube variables of the file. The loader checks
// what it can without Python (names, variables, parameters); the class is
// imported when the network is built (python_constraint.h).
#include <cctype>

#include "sillage/problem/problem_loader.h"

namespace sillage::detail {

namespace {

// A dotted Python name: identifiers separated by dots ("my_ctc", "pkg.ctcs").
bool dotted_name(const std::string& s) {
  if (s.empty() || s.front() == '.' || s.back() == '.') return false;
  bool start = true;
  for (const char ch : s) {
    const unsigned char u = static_cast<unsigned char>(ch);
    if (ch == '.') {
      if (start) return false;  // ".." or a leading dot
      start = true;
      continue;
    }
    if (start && std::isdigit(u)) return false;
    if (!std::isalnum(u) && ch != '_') return false;
    start = false;
  }
  return true;
}

}  // namespace

void ProblemLoader::read_python(const Fields& f, ConstraintSpec& c) {
  c.kind = ConstraintKind::Python;
  const toml::node& mn = f.require("module", "the Python module of the contractor (\"my_ctc\", a file my_ctc.py next to the problem)");
  c.module = f.string(mn, "a module name (string)");
  if (!dotted_name(c.module)) throw ProblemError(doc_.pos(mn), "module = " + doc_.raw(mn), "a Python module name such as \"my_ctc\" or \"pkg.ctcs\"");
  const toml::node& cn = f.require("class", "the sillage.TubeCtc subclass in that module");
  c.cls = f.string(cn, "a class name (string)");
  if (!dotted_name(c.cls) || c.cls.find('.') != std::string::npos)
    throw ProblemError(doc_.pos(cn), "class = " + doc_.raw(cn), "a Python class name such as \"MyCtc\"");
  const toml::node& an = f.require("args", "the tube variables it contracts, in order: [\"x\", \"v\"]");
  for (const toml::node& a : f.array(an, "an array of tube variable names")) c.args.push_back(tube_var(f, a).name);
  if (c.args.empty()) throw ProblemError(doc_.pos(an), "args = []", "at least one tube variable");
  if (const toml::node* pn = f.find("params")) {
    for (const auto& [key, value] : f.table(*pn, "a table of numbers {name = value}, the keyword arguments of the class"))
      c.params[std::string(key.str())] = f.number(value, "a number (the keyword argument '" + std::string(key.str()) + "')");
  }
  std::string args;
  for (const std::string& a : c.args) args += (args.empty() ? "" : ", ") + a;
  c.label = f.where() + ": " + c.module + "." + c.cls + "(" + args + ")";
}

}  // namespace sillage::detail
