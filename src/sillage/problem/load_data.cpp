// [data.NAME]: a CSV table, its path relative to the problem file, its columns checked.
#include "sillage/problem/problem_loader.h"

#include <filesystem>

namespace sillage::detail {

void ProblemLoader::read_data(const std::string& name, const toml::key& key, const toml::node& node) {
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
  if (!std::filesystem::exists(d.path))
    throw ProblemError(doc_.pos(fn), "\"" + file + "\", which names no file (" +
                                         std::filesystem::absolute(d.path).lexically_normal().string() + ")",
                       "a CSV file, its path relative to the problem file's folder");
  try {
    d.table = CsvTable::read(d.path);
  } catch (const Error& e) {
    throw ProblemError(doc_.pos(fn), std::string("an unreadable CSV: ") + e.what(), "a numeric CSV with a header line");
  }
  if (const toml::node* cn = f.find("columns")) {
    for (const toml::node& c : f.array(*cn, "an array of column names")) {
      const std::string col = f.string(c, "a column name (string)");
      if (!d.table.has_column(col))
        throw ProblemError(doc_.pos(c), "the column '" + col + "' missing from " + d.path, "one of: " + column_list(d.table));
      require_column(doc_.pos(c), col, name, d.table);  // listed: read
    }
  }
  p_.data.push_back(std::move(d));
}

}  // namespace sillage::detail
