#include "sillage/problem/load_problem.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <string_view>

#include "sillage/problem/angle_terms.h"
#include "sillage/problem/problem_loader.h"
#include "sillage/read_file.h"

namespace sillage {

namespace detail {

namespace {

constexpr std::uint64_t kFnvPrime = 1099511628211ull;

std::uint64_t fnv1a(std::string_view text, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : text) h = (h ^ c) * kFnvPrime;
  return h;
}

// The tables' names, columns and numbers folded into h, a 64-bit word at a
// time in four independent lanes (one chain would wait on each multiplication;
// plaza1's 136 000 cells, folded in one chain, were 1.8 % of its parse +
// build): the same problem text on other data has another hash. Text cells are NaN here: they are never read.
std::uint64_t with_tables(std::uint64_t h, const std::vector<DataSpec>& data) {
  for (const DataSpec& d : data) {
    h = fnv1a(d.name, h);
    for (const std::string& c : d.table.columns()) h = fnv1a(c, h);
    std::uint64_t lane[4] = {h, h + 1, h + 2, h + 3};
    for (std::size_t r = 0; r < d.table.nb_rows(); ++r) {
      const std::span<const double> row = d.table.row(r);
      for (std::size_t c = 0; c < row.size(); ++c)
        lane[c % 4] = (lane[c % 4] ^ std::bit_cast<std::uint64_t>(row[c])) * kFnvPrime;
    }
    for (const std::uint64_t l : lane) h = (h ^ l) * kFnvPrime;
  }
  return h;
}

std::string hex(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace

ProblemLoader::ProblemLoader(const std::string& text, const std::string& path) {
  p_.file = path;
  p_.text = text;
  p_.hash = hex(fnv1a(text));  // the tables are folded in when read (run())
  doc_.file = path;
  std::istringstream is(text);
  for (std::string l; std::getline(is, l);) doc_.lines.push_back(l);
  base_ = std::filesystem::path(path).parent_path();
}

Problem ProblemLoader::run() {
  toml::table root;
  try {
    root = toml::parse(p_.text, p_.file);
  } catch (const toml::parse_error& e) {
    throw ProblemError(doc_.pos(e.source()), "invalid TOML: " + std::string(e.description()),
                       "a TOML file (https://toml.io)");
  }
  const Fields top(doc_, root, "the file", {"time", "data", "var", "constraint", "output", "network", "online"});
  if (const toml::node* d = top.find("data"))
    for (auto&& [key, node] : top.table(*d, "tables [data.NAME]")) read_data(std::string(key.str()), key, node);
  p_.hash = hex(with_tables(fnv1a(p_.text), p_.data));
  read_time(top.table(top.require("time", "a table [time] with domain = [t0, tf]"), "a table [time]"));
  const toml::node& vars = top.require("var", "tables [var.NAME]");
  for (auto&& [key, node] : top.table(vars, "tables [var.NAME]")) read_var(std::string(key.str()), key, node);
  const toml::node& cs = top.require("constraint", "one or more [[constraint]] tables");
  for (const toml::node& c : top.array(cs, "[[constraint]] tables")) read_constraint(top, c);
  check_angle_uses(p_);
  if (const toml::node* o = top.find("output")) read_output(top.table(*o, "a table [output]"));
  if (const toml::node* n = top.find("network")) read_network(top.table(*n, "a table [network]"));
  if (const toml::node* n = top.find("online")) read_online(top.table(*n, "a table [online]"));
  return std::move(p_);
}

}  // namespace detail

Problem parse_problem(const std::string& text, const std::string& path) { return detail::ProblemLoader(text, path).run(); }

Problem load_problem(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw ProblemError(SourcePos{path}, "a directory", "a problem file (TOML)");
  std::ifstream is(path, std::ios::binary);
  if (!is && !std::filesystem::exists(path))
    throw ProblemError(SourcePos{path}, "no such file", "a problem file (TOML)");
  if (!is) throw ProblemError(SourcePos{path}, "a file that cannot be read", "a readable problem file (TOML)");
  // Size-limited: a device (/dev/zero) or a huge file is refused, not read without end.
  return parse_problem(read_file_bytes(path, "load_problem", "a problem file (TOML)"), path);
}

}  // namespace sillage
