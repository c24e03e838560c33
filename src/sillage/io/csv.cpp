#include "sillage/io/csv.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "sillage/error.h"

namespace sillage {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    const auto a = cell.find_first_not_of(" \t\r");
    const auto b = cell.find_last_not_of(" \t\r");
    cells.push_back(a == std::string::npos ? std::string() : cell.substr(a, b - a + 1));
  }
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

CsvTable CsvTable::read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("CsvTable::read: cannot open " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

CsvTable CsvTable::parse(const std::string& text, const std::string& source) {
  CsvTable t;
  t.source_ = source;
  std::istringstream in(text);
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    const std::vector<std::string> cells = split(line);
    if (t.columns_.empty()) {
      t.columns_ = cells;
      continue;
    }
    const std::string where = source + ":" + std::to_string(line_no);
    if (cells.size() != t.columns_.size()) {
      throw ParseError(where + ": " + std::to_string(cells.size()) + " cells, the header has " +
                       std::to_string(t.columns_.size()));
    }
    std::vector<double> row(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string& s = cells[c];
      const char* end = s.data() + s.size();
      const auto [p, ec] = std::from_chars(s.data(), end, row[c]);
      if (s.empty() || ec != std::errc() || p != end || !std::isfinite(row[c])) {
        throw ParseError(where + ": column '" + t.columns_[c] + "': '" + s + "' is not a finite number");
      }
    }
    t.rows_.push_back(std::move(row));
  }
  if (t.columns_.empty()) throw ParseError(source + ": no header line");
  return t;
}

bool CsvTable::has_column(const std::string& name) const {
  for (const auto& c : columns_)
    if (c == name) return true;
  return false;
}

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns_.size(); ++i)
    if (columns_[i] == name) return i;
  std::string have;
  for (const auto& c : columns_) have += (have.empty() ? "" : ", ") + c;
  throw Error(source_ + ": no column '" + name + "' (columns: " + have + ")");
}

std::vector<double> CsvTable::values(const std::string& name) const {
  const std::size_t c = column(name);
  std::vector<double> v;
  v.reserve(rows_.size());
  for (const auto& r : rows_) v.push_back(r[c]);
  return v;
}

}  // namespace sillage
