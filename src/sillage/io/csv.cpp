#include "sillage/io/csv.h"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <span>
#include <string_view>
#include <unordered_map>

#include "sillage/error.h"
#include "sillage/read_file.h"
#include "sillage/text_utf8.h"

namespace sillage {

namespace {

std::string_view trimmed(std::string_view cell) {
  const auto a = cell.find_first_not_of(" \t\r");
  return a == std::string_view::npos ? std::string_view() : cell.substr(a, cell.find_last_not_of(" \t\r") - a + 1);
}

// The quoted cell opening at `first` (RFC 4180: "" stands for a quote; text
// after the closing quote is refused): its text, in `unquoted` when it had ""
// (reserved to the line's size: earlier views stay valid); `comma` set to the
// comma that ends it, or the line's end; source and line_no name the line in errors.
std::string_view quoted_cell(std::string_view line, std::size_t first, std::string& unquoted, std::size_t& comma,
                             const std::string& source, std::size_t line_no) {
  const auto where = [&] { return source + ":" + std::to_string(line_no); };
  std::size_t close = first + 1;
  bool escaped = false;
  for (; close < line.size(); ++close) {
    if (line[close] != '"') continue;
    if (close + 1 < line.size() && line[close + 1] == '"') {
      escaped = true;
      ++close;
      continue;
    }
    break;
  }
  if (close >= line.size())
    throw ParseError(where() + ": a quote opened at column " + std::to_string(first + 1) + " is not closed on its line");
  comma = std::min(line.find(',', close), line.size());
  if (!trimmed(line.substr(close + 1, comma - close - 1)).empty())
    throw ParseError(where() + ": text after the quoted cell closed at column " + std::to_string(close + 1));
  const std::string_view inner = line.substr(first + 1, close - first - 1);
  if (!escaped) return inner;
  const std::size_t from = unquoted.size();
  for (std::size_t i = 0; i < inner.size(); ++i) {
    unquoted.push_back(inner[i]);
    if (inner[i] == '"') ++i;  // "" is one quote
  }
  return std::string_view(unquoted).substr(from);
}

// The cells of a line, blanks around them removed (views into the line: no
// stream, no copy; tables of 10^5 rows are read by `sillage check`). A cell
// in double quotes (R, spreadsheets and pandas write text so) may hold commas.
void split(std::string_view line, std::vector<std::string_view>& cells, std::string& unquoted,
           const std::string& source, std::size_t line_no) {
  cells.clear();
  unquoted.clear();
  unquoted.reserve(line.size());
  if (line.empty()) return;
  for (std::size_t at = 0;;) {
    const std::size_t first = line.find_first_not_of(" \t", at);
    std::size_t comma = 0;
    if (first != std::string_view::npos && line[first] == '"') {
      cells.push_back(trimmed(quoted_cell(line, first, unquoted, comma, source, line_no)));
    } else {
      comma = std::min(line.find(',', at), line.size());
      cells.push_back(trimmed(line.substr(at, comma - at)));
    }
    if (comma == line.size()) return;
    at = comma + 1;
  }
}

// The cell as a number: what from_chars reads, also after a leading '+'
// (printf's %+f); a decimal below the smallest subnormal reads as its nearest
// double (0 or the smallest), which the one-ulp cell of a problem encloses.
// False if the whole cell is not a finite number.
bool number(std::string_view cell, double& v) {
  if (cell.size() > 1 && cell[0] == '+' && (std::isdigit(static_cast<unsigned char>(cell[1])) || cell[1] == '.'))
    cell.remove_prefix(1);
  const char* end = cell.data() + cell.size();
  const auto [p, ec] = std::from_chars(cell.data(), end, v);
  if (p != end || cell.empty()) return false;
  if (ec == std::errc::result_out_of_range) {  // an overflow (not finite) or an underflow (a tiny finite number)
    v = std::strtod(std::string(cell).c_str(), nullptr);
    return std::isfinite(v);
  }
  return ec == std::errc() && std::isfinite(v);
}

// The text without its UTF-8 byte order mark; ParseError for UTF-16 (a byte
// order mark FF FE or FE FF, or NUL bytes), which would read as garbage.
std::string_view checked_encoding(std::string_view text, const std::string& source) {
  std::string_view v = text;
  if (v.substr(0, 2) == "\xFF\xFE" || v.substr(0, 2) == "\xFE\xFF") {
    throw ParseError(source + ": the file is UTF-16 (it starts with a byte order mark); convert it to UTF-8");
  }
  if (v.find('\0') != std::string_view::npos) {
    throw ParseError(source + ": the file contains NUL bytes (UTF-16 or binary?); convert it to UTF-8 text");
  }
  if (v.substr(0, 3) == "\xEF\xBB\xBF") v.remove_prefix(3);
  return v;
}

// The line starting at `at` (without its end: \n, \r\n or a lone \r); moves `at` past it.
std::string_view next_line(std::string_view text, std::size_t& at) {
  std::size_t end = at;
  while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
  const std::string_view line = text.substr(at, end - at);
  at = end + (end < text.size() && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
  return line;
}

// Column names must be non-empty and distinct (1-based column numbers in errors).
void check_header(const std::vector<std::string>& names, const std::string& where) {
  std::unordered_map<std::string_view, std::size_t> first;  // a hash: headers may be huge
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) {
      throw ParseError(where + ": column " + std::to_string(i + 1) + " of the header has no name");
    }
    const auto [it, added] = first.emplace(names[i], i);
    if (!added) {
      throw ParseError(where + ": columns " + std::to_string(it->second + 1) + " and " + std::to_string(i + 1) +
                       " of the header have the same name '" + detail::quote_text(names[i]) + "'");
    }
  }
}

bool blank(char c) { return c == ' ' || c == '\t'; }

// The row starting at `at`, if it is a plain one: n finite numbers separated
// by commas, blanks around them, then the end of the line (\n, \r\n, \r or
// the end of the text). Each number is read where it lies, in one pass over
// the line (the way of almost every line of a data file); then `at` moves past
// the line. Anything else (a comment, a blank line, a fault) returns false
// and leaves `at`: the general path reads that line and names the fault.
bool plain_row(std::string_view text, std::size_t& at, std::size_t n, double* out) {
  const char *p = text.data() + at, *const end = text.data() + text.size();
  for (std::size_t c = 0; c < n; ++c) {
    while (p < end && blank(*p)) ++p;
    const auto [q, ec] = std::from_chars(p, end, out[c]);
    if (ec != std::errc() || !std::isfinite(out[c])) return false;
    p = q;
    while (p < end && blank(*p)) ++p;
    if (c + 1 < n) {
      if (p == end || *p != ',') return false;
      ++p;
    }
  }
  if (p == end) {
    at = text.size();
  } else if (*p == '\n') {
    at = static_cast<std::size_t>(p + 1 - text.data());
  } else if (*p == '\r') {
    at = static_cast<std::size_t>(p + (p + 1 < end && p[1] == '\n' ? 2 : 1) - text.data());
  } else {
    return false;
  }
  return true;
}

}  // namespace

CsvTable CsvTable::read(const std::string& path) {
  return parse(read_file_bytes(path, "CsvTable::read", "a CSV file"), path);
}

CsvTable CsvTable::parse(const std::string& text, const std::string& source) {
  CsvTable t;
  t.source_ = source;
  const std::string_view body = checked_encoding(text, source);
  std::size_t line_no = 0, header_line = 0;
  std::vector<std::string_view> cells;
  std::string unquoted;  // the quoted cells of a line that had ""
  std::vector<double> row;
  for (std::size_t at = 0; at < body.size();) {
    if (const std::size_t n = t.columns_.size(); n > 0) {
      row.resize(n);
      const std::size_t from = at;
      if (plain_row(body, at, n, row.data())) {
        // Room for as many rows as the first one's length suggests: at most
        // 4.5 bytes per byte of text (one-digit cells), what such a table needs.
        if (t.lines_.empty()) {
          const std::size_t rows = (body.size() - from) / (at - from) + 1;
          t.cells_.reserve(rows * n + rows * n / 8);
          t.lines_.reserve(rows + rows / 8);
        }
        t.cells_.insert(t.cells_.end(), row.begin(), row.end());
        t.lines_.push_back(++line_no);
        continue;
      }
    }
    const std::string_view line = next_line(body, at);
    ++line_no;
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line[first] == '#') continue;
    split(line, cells, unquoted, source, line_no);
    const auto where = [&] { return source + ":" + std::to_string(line_no); };
    if (t.columns_.empty()) {
      const std::vector<std::string> names(cells.begin(), cells.end());
      check_header(names, where());
      t.columns_ = names;
      t.not_numbers_.assign(names.size(), std::string());
      header_line = line_no;
      continue;
    }
    if (cells.size() != t.columns_.size()) {
      throw ParseError(where() + ": " + std::to_string(cells.size()) + " cells, the header (line " +
                       std::to_string(header_line) + ") has " + std::to_string(t.columns_.size()));
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string_view cell = cells[c];
      double v = 0;
      if (!number(cell, v)) {
        // Text (a label, a missing value): the column is kept, and reading it
        // is an error naming this cell, its first one.
        v = std::numeric_limits<double>::quiet_NaN();
        if (t.not_numbers_[c].empty())
          t.not_numbers_[c] = where() + ": column '" + detail::quote_text(t.columns_[c]) + "': '" +
                              detail::quote_text(std::string(cell)) + "' is not a finite number";
      }
      t.cells_.push_back(v);
    }
    t.lines_.push_back(line_no);
  }
  if (t.columns_.empty()) throw ParseError(source + ": no header line");
  return t;
}

std::span<const double> CsvTable::row(std::size_t i) const {
  if (i >= nb_rows()) {
    throw OutOfRangeError(source_ + ": no row " + std::to_string(i) + " (" + rows_text() + ")");
  }
  const std::size_t n = columns_.size();
  return {cells_.data() + i * n, n};
}

std::size_t CsvTable::line(std::size_t i) const {
  row(i);  // the range check and its message
  return lines_[i];
}

CsvTable CsvTable::without_rows(std::size_t first, std::size_t last) const {
  if (first > last || last > nb_rows())
    throw OutOfRangeError(source_ + ": no rows [" + std::to_string(first) + ", " + std::to_string(last) + ") (" +
                          rows_text() + ")");
  CsvTable t = *this;
  const std::size_t n = columns_.size();
  t.cells_.erase(t.cells_.begin() + static_cast<std::ptrdiff_t>(first * n),
                 t.cells_.begin() + static_cast<std::ptrdiff_t>(last * n));
  t.lines_.erase(t.lines_.begin() + static_cast<std::ptrdiff_t>(first), t.lines_.begin() + static_cast<std::ptrdiff_t>(last));
  return t;
}

std::string CsvTable::where(std::size_t i) const { return source_ + ":" + std::to_string(line(i)); }

std::string CsvTable::rows_text() const {
  if (nb_rows() == 0) return "the table has no rows";
  return "the table has " + std::to_string(nb_rows()) + " rows: 0 to " + std::to_string(nb_rows() - 1);
}

bool CsvTable::has_column(const std::string& name) const {
  for (const auto& c : columns_)
    if (c == name) return true;
  return false;
}

namespace {

std::size_t index_of(const std::vector<std::string>& columns, const std::string& name, const std::string& source) {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  std::string have;
  for (const auto& c : columns) have += (have.empty() ? "" : ", ") + c;
  throw Error(source + ": no column '" + detail::quote_text(name) + "' (columns: " + detail::quote_text(have, 200) + ")");
}

}  // namespace

std::size_t CsvTable::column(const std::string& name) const {
  const std::size_t c = index_of(columns_, name, source_);
  check_numeric(c);
  return c;
}

bool CsvTable::is_numeric(const std::string& name) const {
  return not_numbers_[index_of(columns_, name, source_)].empty();
}

void CsvTable::check_numeric(std::size_t c) const {
  if (c >= columns_.size()) {
    throw OutOfRangeError(source_ + ": no column " + std::to_string(c) + " (the table has " +
                          std::to_string(columns_.size()) + ")");
  }
  if (!not_numbers_[c].empty()) throw ParseError(not_numbers_[c]);
}

std::vector<double> CsvTable::values(const std::string& name) const {
  const std::size_t c = column(name);
  std::vector<double> v(nb_rows());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = cells_[i * columns_.size() + c];
  return v;
}

}  // namespace sillage
