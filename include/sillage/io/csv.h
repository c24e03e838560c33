#pragma once
// CsvTable: a CSV file with one header line (the datasets of ../shared/data:
// odometry, ranges, ground truth; a robot's logs). Every cell that is read
// must be a finite number; a column with a cell that is not (a text column of
// a log: a frame name, a label, a missing value) is kept, and reading it
// (column(), values(), a problem file's expression) is a ParseError that names
// its first such cell: file, line, column. A short row or a missing column is
// a ParseError that names the file and the line. Header names are non-empty
// and distinct. A cell in double quotes (RFC 4180: R, spreadsheets, pandas)
// may hold commas, "" stands for a quote; a number may carry a '+' sign.
// Cells are quoted in messages up to 60 characters.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace sillage {

// A CSV file with one header line; reading a cell that is not a number is a ParseError naming file, line, column.
class CsvTable {
 public:
  // Reads `path` (comma-separated; blank lines and lines starting with '#'
  // are skipped; lines end with \n, \r\n or \r; a UTF-8 byte order mark is
  // skipped, UTF-16 is a ParseError). Error if the file cannot be read, or
  // is larger than max_file_bytes() (read_file.h: 2 GiB by default).
  static CsvTable read(const std::string& path);
  // Parses text already in memory; `source` names it in error messages.
  static CsvTable parse(const std::string& text, const std::string& source);

  // The header names, in order.
  const std::vector<std::string>& columns() const { return columns_; }
  // Number of data rows.
  std::size_t nb_rows() const { return lines_.size(); }
  // Row i, one value per column (OutOfRangeError if i >= nb_rows()); a cell
  // that is not a number is NaN there: read by index only the columns that
  // column() or check_numeric() accepted.
  std::span<const double> row(std::size_t i) const;
  // "the table has 3 rows: 0 to 2", for messages about rows.
  std::string rows_text() const;
  // The file (or the source given to parse) the table was read from.
  const std::string& source() const { return source_; }
  // The line of row i in the file, 1-based (blank and comment lines counted; OutOfRangeError if i >= nb_rows()).
  std::size_t line(std::size_t i) const;
  // "ranges.csv:12": where row i is written, for messages about it.
  std::string where(std::size_t i) const;
  // True if a column is called name.
  bool has_column(const std::string& name) const;
  // Index of a column of numbers: Error naming the file and the columns it
  // has if there is none called name, ParseError naming the first cell that
  // is not a finite number if it is a text column.
  std::size_t column(const std::string& name) const;
  // True if every cell of the column is a finite number (Error if there is no such column).
  bool is_numeric(const std::string& name) const;
  // ParseError naming the first cell of column c that is not a finite number, if any.
  void check_numeric(std::size_t c) const;
  // The values of a column of numbers, in file order (the errors of column()).
  std::vector<double> values(const std::string& name) const;
  // The same table without rows [first, last) (OutOfRangeError unless
  // first <= last <= nb_rows()): the rows left keep their lines in the file,
  // so that messages still point at them (sillage explain drops runs of rows).
  CsvTable without_rows(std::size_t first, std::size_t last) const;

 private:
  std::string source_;
  std::vector<std::string> columns_;
  std::vector<double> cells_;       // row after row: one allocation, not one per row
  std::vector<std::size_t> lines_;  // per row
  std::vector<std::string> not_numbers_;  // per column: its first cell that is not a number, "" if none
};

}  // namespace sillage
