// CsvTable: parsing, column access, errors that name file, line and column,
// and the real datasets of ../shared/data when present.
#include <gtest/gtest.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <filesystem>

#include "sillage/error.h"
#include "sillage/io/csv.h"

using namespace sillage;

TEST(Csv, ParsesHeaderAndRows) {
  const CsvTable t = CsvTable::parse("# comment\nt_s, x\n1.5,2\n\n2.5,-3e-2\r\n", "mem");
  ASSERT_EQ(t.columns(), (std::vector<std::string>{"t_s", "x"}));
  ASSERT_EQ(t.nb_rows(), 2u);
  EXPECT_EQ(t.values("x"), (std::vector<double>{2.0, -0.03}));
  EXPECT_EQ(t.row(1)[0], 2.5);
  EXPECT_TRUE(t.has_column("t_s"));
  EXPECT_FALSE(t.has_column("y"));
}

// Each row keeps its line in the file, comments, blank lines and the header counted.
TEST(Csv, RowsKnowTheirLines) {
  const CsvTable t = CsvTable::parse("# comment\nt_s, x\n1.5,2\n\n2.5,-3e-2\r\n", "mem");
  EXPECT_EQ(t.source(), "mem");
  EXPECT_EQ(t.line(0), 3u);
  EXPECT_EQ(t.line(1), 5u);
  EXPECT_EQ(t.where(1), "mem:5");
  EXPECT_THROW(t.line(2), OutOfRangeError);
}

TEST(Csv, ErrorsSayWhere) {
  const CsvTable x = CsvTable::parse("a,b\n1,2\n3,x\n", "f.csv");  // b is read as text: an error when read
  try {
    x.column("b");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_STREQ(e.what(), "f.csv:3: column 'b': 'x' is not a finite number");
  }
  EXPECT_THROW(x.values("b"), ParseError);
  EXPECT_THROW(CsvTable::parse("a,b\n1\n", "f.csv"), ParseError);
  EXPECT_THROW(CsvTable::parse("a\nnan\n", "f.csv").values("a"), ParseError);
  EXPECT_THROW(CsvTable::parse("", "f.csv"), ParseError);
  EXPECT_THROW(CsvTable::read("/nonexistent/file.csv"), Error);
  EXPECT_THROW(CsvTable::read(testing::TempDir()), Error);  // a folder
  {
    const std::string empty = testing::TempDir() + "empty.csv", small = testing::TempDir() + "small.csv";
    std::FILE* f = std::fopen(empty.c_str(), "w");
    std::fclose(f);
    EXPECT_THROW(CsvTable::read(empty), ParseError);  // no header line
    f = std::fopen(small.c_str(), "w");
    std::fputs("t,x\n0,1.5\n2,-3\n", f);
    std::fclose(f);
    const CsvTable s = CsvTable::read(small);
    ASSERT_EQ(s.nb_rows(), 2u);
    EXPECT_EQ(s.row(1)[1], -3.0);
    EXPECT_EQ(s.line(1), 3u);
  }
  const CsvTable t = CsvTable::parse("a\n1\n", "f.csv");
  try {
    t.column("z");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("columns: a"), std::string::npos) << e.what();
  }
}

TEST(Csv, ReadsThePlaza1Dataset) {
  const std::filesystem::path dir = std::filesystem::path(SILLAGE_SHARED_DIR) / "data" / "plaza1";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no dataset at " << dir;
  const CsvTable odo = CsvTable::read((dir / "odometry.csv").string());
  EXPECT_EQ(odo.nb_rows(), 9657u);
  const CsvTable beacons = CsvTable::read((dir / "beacons.csv").string());
  EXPECT_EQ(beacons.nb_rows(), 4u);
  EXPECT_EQ(beacons.values("beacon_id"), (std::vector<double>{0, 1, 5, 6}));
}

namespace {

// The error of reading the table, then each of its columns (a column with a
// cell that is not a number is kept by parse and refused when read).
std::string csv_error(const std::string& text) {
  try {
    const CsvTable t = CsvTable::parse(text, "f.csv");
    for (const std::string& c : t.columns()) (void)t.column(c);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(Csv, EncodingsAndLineEnds) {
  // A UTF-8 byte order mark is not part of the first name.
  EXPECT_EQ(CsvTable::parse("\xEF\xBB\xBFt,x\n1,2\n", "f.csv").columns(), (std::vector<std::string>{"t", "x"}));
  // CR-only, CRLF and LF line ends.
  for (const std::string eol : {"\r", "\r\n", "\n"}) {
    const CsvTable t = CsvTable::parse("t,x" + eol + "1,2" + eol + "3,4" + eol, "f.csv");
    EXPECT_EQ(t.nb_rows(), 2u);
    EXPECT_EQ(t.values("x"), (std::vector<double>{2, 4}));
  }
  EXPECT_EQ(CsvTable::parse("t\r1\r\r2", "f.csv").nb_rows(), 2u);
  EXPECT_EQ(csv_error(std::string("\xFF\xFEt\0,\0x\0", 8)),
            "f.csv: the file is UTF-16 (it starts with a byte order mark); convert it to UTF-8");
  EXPECT_EQ(csv_error(std::string("\xFE\xFF\0t", 4)),
            "f.csv: the file is UTF-16 (it starts with a byte order mark); convert it to UTF-8");
  EXPECT_EQ(csv_error(std::string("t\0,\0x\0", 6)),
            "f.csv: the file contains NUL bytes (UTF-16 or binary?); convert it to UTF-8 text");
}

TEST(Csv, HeaderNamesAreNonEmptyAndDistinct) {
  EXPECT_EQ(csv_error("t,x,,y\n1,2,3,4\n"), "f.csv:1: column 3 of the header has no name");
  EXPECT_EQ(csv_error("# c\nt,x,y,x\n1,2,3,4\n"), "f.csv:2: columns 2 and 4 of the header have the same name 'x'");
  EXPECT_EQ(csv_error("t,x\n1,2,3\n"), "f.csv:2: 3 cells, the header (line 1) has 2");
}

TEST(Csv, LongCellsAreQuotedBriefly) {
  const std::string cell(10'000'000, 'z');
  const std::string m = csv_error("t\n" + cell + "\n");
  EXPECT_EQ(m, "f.csv:2: column 't': '" + std::string(60, 'z') + "...' is not a finite number");
  // Cells that are not UTF-8 still give a UTF-8 message.
  EXPECT_EQ(csv_error("t\n\xE9\n"), "f.csv:2: column 't': '\xEF\xBF\xBD' is not a finite number");
}

// A log's text columns (a frame name, a label, a missing value) do not stop
// the table from being read: reading them does, naming their first such cell.
TEST(Csv, TextColumnsAreKeptUntilRead) {
  const CsvTable t = CsvTable::parse("t, frame, x, note\n0.5, base_link, 1.5, \n1.0, odom, -2, ok\n1.5, map, 3e-1, 7\n",
                                     "log.csv");
  ASSERT_EQ(t.nb_rows(), 3u);
  EXPECT_EQ(t.values("t"), (std::vector<double>{0.5, 1.0, 1.5}));
  EXPECT_EQ(t.values("x"), (std::vector<double>{1.5, -2.0, 0.3}));
  EXPECT_TRUE(t.is_numeric("x"));
  EXPECT_FALSE(t.is_numeric("frame"));
  EXPECT_FALSE(t.is_numeric("note"));
  EXPECT_TRUE(t.has_column("frame"));
  EXPECT_THROW(t.is_numeric("y"), Error);
  EXPECT_EQ(t.column("x"), 2u);
  EXPECT_NO_THROW(t.check_numeric(2));
  EXPECT_THROW(t.check_numeric(4), OutOfRangeError);
  const auto message = [&](const std::string& name) {
    try {
      (void)t.column(name);
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("frame"), "log.csv:2: column 'frame': 'base_link' is not a finite number");
  EXPECT_EQ(message("note"), "log.csv:2: column 'note': '' is not a finite number");  // the first one: a missing value
  EXPECT_THROW(t.values("note"), ParseError);
  EXPECT_THROW(t.check_numeric(1), ParseError);
  EXPECT_TRUE(std::isnan(t.row(0)[1]));
  EXPECT_TRUE(std::isnan(t.row(0)[3]));
  EXPECT_EQ(t.row(2)[3], 7.0);  // a number in a text column is still read as one
  EXPECT_EQ(t.row(1)[2], -2.0);
}

// Forms of real exports: quoted names and cells (R's write.csv, spreadsheets,
// pandas), commas and "" inside quotes, a '+' sign (printf's %+f), a number
// below the smallest subnormal.
TEST(Csv, QuotedCellsSignsAndTinyNumbers) {
  const CsvTable t = CsvTable::parse(
      "\"t\",\"name\",\"x\"\n1,\"a, b\",+0.5\n2, \"say \"\"hi\"\"\" ,\"1e-400\"\n3,plain,\"-2.5\"\n", "f.csv");
  EXPECT_EQ(t.columns(), (std::vector<std::string>{"t", "name", "x"}));
  ASSERT_EQ(t.nb_rows(), 3u);
  EXPECT_EQ(t.values("t"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(t.values("x"), (std::vector<double>{0.5, 0.0, -2.5}));  // 1e-400: its nearest double
  EXPECT_EQ(csv_error("t,name\n1,\"a, b\"\n"), "f.csv:2: column 'name': 'a, b' is not a finite number");
  EXPECT_EQ(csv_error("t,name\n1,\"say \"\"hi\"\"\"\n"), "f.csv:2: column 'name': 'say \"hi\"' is not a finite number");
  EXPECT_EQ(csv_error("t,x\n1,\"2\n3\"\n"), "f.csv:2: a quote opened at column 3 is not closed on its line");
  EXPECT_EQ(csv_error("t,x\n1,\"2\"5\n"), "f.csv:2: text after the quoted cell closed at column 5");
  for (const std::string bad : {"+-1", "+", "++1", "1e400", "-1e400", "+inf"})
    EXPECT_EQ(csv_error("x\n" + bad + "\n"), "f.csv:2: column 'x': '" + bad + "' is not a finite number") << bad;
  EXPECT_EQ(CsvTable::parse("x\n+.5\n1e-320\n", "f.csv").values("x"), (std::vector<double>{0.5, 1e-320}));
}

TEST(Csv, RowOutOfRange) {
  const CsvTable t = CsvTable::parse("a\n1\n2\n", "f.csv");
  EXPECT_EQ(t.row(1)[0], 2.0);
  try {
    t.row(2);
    FAIL();
  } catch (const OutOfRangeError& e) {
    EXPECT_STREQ(e.what(), "f.csv: no row 2 (the table has 2 rows: 0 to 1)");
  }
}

// Data lines are read in one pass where they are plain (numbers, commas,
// blanks); everything else goes through the general path. Random tables in
// every form the format allows (blanks and tabs around cells, the three line
// ends, comments, blank lines, no final line end) give the exact values and
// lines, and a fault anywhere is named at its line and column.
TEST(Csv, EveryFormOfLineReadsAlike) {
  std::mt19937_64 rng(7);
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); };
  const char* blanks[] = {"", "", " ", "\t", "  \t "};
  const char* eols[] = {"\n", "\r\n", "\r"};
  for (int trial = 0; trial < 300; ++trial) {
    const int ncols = 1 + pick(4), nrows = 1 + pick(12);
    const char* eol = eols[pick(3)];  // one per file: "\r" then an empty "\n" line would read as "\r\n"
    std::string text = "c0";
    for (int c = 1; c < ncols; ++c) text += ", c" + std::to_string(c);
    text += eol;
    std::size_t line = 1;
    std::vector<std::vector<double>> values;
    std::vector<std::size_t> lines;
    for (int r = 0; r < nrows; ++r) {
      while (pick(4) == 0) {  // comments and blank lines between rows
        text += pick(2) ? std::string(blanks[pick(5)]) + "# note, 1, 2" : std::string(blanks[pick(5)]);
        text += eol;
        ++line;
      }
      std::vector<double> row;
      for (int c = 0; c < ncols; ++c) {
        const double v = std::ldexp(static_cast<double>(static_cast<std::int64_t>(rng() >> 11)) * (pick(2) ? 1 : -1),
                                    pick(80) - 60);
        char cell[40];
        std::snprintf(cell, sizeof cell, pick(2) ? "%.17g" : "%.6e", v);
        row.push_back(std::strtod(cell, nullptr));
        text += std::string(blanks[pick(5)]) + cell + blanks[pick(5)] + (c + 1 < ncols ? "," : "");
      }
      values.push_back(row);
      lines.push_back(++line);
      if (r + 1 < nrows || pick(2)) text += eol;
    }
    const CsvTable t = CsvTable::parse(text, "f.csv");
    ASSERT_EQ(t.nb_rows(), values.size()) << text;
    for (std::size_t r = 0; r < values.size(); ++r) {
      EXPECT_EQ(std::vector<double>(t.row(r).begin(), t.row(r).end()), values[r]) << text;
      EXPECT_EQ(t.line(r), lines[r]) << text;
    }
    // One cell of one row made wrong: named with its line and column.
    const std::size_t r = static_cast<std::size_t>(pick(nrows));
    const int c = pick(ncols);
    const char* bad[] = {"1.5x", "nan", "1 2", "+-1", "inf", "0x10", "--1"};
    const std::string b = bad[pick(7)];
    std::string faulty;
    std::size_t at = 0, line_no = 0;
    while (at < text.size()) {  // rebuild the text line by line, the chosen row with its bad cell
      std::size_t end = text.find_first_of("\r\n", at);
      if (end == std::string::npos) end = text.size();
      std::string l = text.substr(at, end - at);
      std::size_t next = end + (end < text.size() && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
      ++line_no;
      if (line_no == lines[r]) {
        std::size_t from = 0;
        for (int k = 0; k < c; ++k) from = l.find(',', from) + 1;
        const std::size_t to = std::min(l.find(',', from), l.size());
        l = l.substr(0, from) + " " + b + " " + l.substr(to);
      }
      faulty += l + text.substr(end, std::min(next, text.size()) - end);
      at = next;
    }
    const std::string m = csv_error(faulty);
    EXPECT_EQ(m, "f.csv:" + std::to_string(lines[r]) + ": column 'c" + std::to_string(c) + "': '" + b +
                     "' is not a finite number")
        << faulty;
  }
}

namespace {

// The format read the plain way, line by line (the reference for the
// one-pass reading of plain rows): blank and '#' lines skipped, cells split
// at commas and trimmed, a '+' sign dropped; a cell that is not a whole finite number is NaN and
// marks its column as text. "error" for a row of another length than the
// header, which CsvTable must refuse.
struct Reference {
  std::vector<std::vector<double>> rows;  // NaN where a cell is not a number
  std::vector<std::size_t> lines;
  std::vector<std::size_t> first_bad;  // per column: the line of its first cell that is not a number, 0 if none
  bool error = false;                  // the table refused (a row of another length)
};

Reference read_plainly(const std::string& text) {
  Reference r;
  std::size_t at = 0, line_no = 0, ncols = 0;
  while (at < text.size()) {
    std::size_t end = text.find_first_of("\r\n", at);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(at, end - at);
    at = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
    ++line_no;
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    std::vector<std::string> cells;
    for (std::size_t from = 0;;) {
      const std::size_t comma = std::min(line.find(',', from), line.size());
      std::string cell = line.substr(from, comma - from);
      const std::size_t a = cell.find_first_not_of(" \t"), b = cell.find_last_not_of(" \t");
      cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
      if (comma == line.size()) break;
      from = comma + 1;
    }
    if (ncols == 0) {
      ncols = cells.size();
      r.first_bad.assign(ncols, 0);
      continue;
    }
    if (cells.size() != ncols) {
      r.error = true;
      return r;
    }
    std::vector<double> row;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      std::string c = cells[k];
      if (c.size() > 1 && c[0] == '+' && (std::isdigit(static_cast<unsigned char>(c[1])) || c[1] == '.')) c.erase(0, 1);
      double v = 0;
      const auto [p, ec] = std::from_chars(c.data(), c.data() + c.size(), v);
      if (c.empty() || ec != std::errc() || p != c.data() + c.size() || !std::isfinite(v)) {
        v = std::nan("");
        if (r.first_bad[k] == 0) r.first_bad[k] = line_no;
      }
      row.push_back(v);
    }
    r.rows.push_back(row);
    r.lines.push_back(line_no);
  }
  return r;
}

}  // namespace

// Valid tables mutated at random (characters replaced, inserted or removed
// among those that matter to the format): CsvTable reads what the plain
// reference reads, values and lines, refuses what it refuses, and refuses to
// read the columns it finds a cell that is not a number in, naming the first.
TEST(Csv, MutatedTablesReadAsThePlainReference) {
  std::mt19937_64 rng(11);
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  const std::string alphabet = "0123456789.,-+eE \t\r\n#xn";
  int parsed = 0, refused = 0, text_columns = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = "a,b,c\n";
    for (int r = 0; r < 6; ++r)
      text += std::to_string(pick(2000)) + "." + std::to_string(pick(100)) + ", -" + std::to_string(pick(50)) +
              "e-" + std::to_string(pick(5)) + " ,\t" + std::to_string(pick(9)) + "\n";
    for (std::size_t m = 1 + pick(3); m > 0; --m) {
      const std::size_t i = 6 + pick(text.size() - 6);  // the header stays
      const char c = alphabet[pick(alphabet.size())];
      switch (pick(3)) {
        case 0: text[i] = c; break;
        case 1: text.insert(text.begin() + static_cast<std::ptrdiff_t>(i), c); break;
        default: text.erase(i, 1);
      }
    }
    const Reference ref = read_plainly(text);
    try {
      const CsvTable t = CsvTable::parse(text, "f.csv");
      ++parsed;
      ASSERT_FALSE(ref.error) << text;
      ASSERT_EQ(t.nb_rows(), ref.rows.size()) << text;
      for (std::size_t r = 0; r < ref.rows.size(); ++r) {
        for (std::size_t c = 0; c < 3; ++c) {
          if (std::isnan(ref.rows[r][c])) EXPECT_TRUE(std::isnan(t.row(r)[c])) << text;
          else EXPECT_EQ(t.row(r)[c], ref.rows[r][c]) << text;
        }
        EXPECT_EQ(t.line(r), ref.lines[r]) << text;
      }
      for (std::size_t c = 0; c < 3; ++c) {  // a text column: refused when read, at its first cell that is not a number
        const std::string name = t.columns()[c];
        if (ref.first_bad[c] == 0) {
          EXPECT_TRUE(t.is_numeric(name)) << text;
          continue;
        }
        ++text_columns;
        EXPECT_FALSE(t.is_numeric(name)) << text;
        try {
          (void)t.column(name);
          ADD_FAILURE() << text;
        } catch (const ParseError& e) {
          const std::string at = "f.csv:" + std::to_string(ref.first_bad[c]) + ": column '" + name + "': ";
          EXPECT_EQ(std::string(e.what()).rfind(at, 0), 0u)
              << e.what() << "\n" << text;
        }
      }
    } catch (const ParseError&) {
      ++refused;
      EXPECT_TRUE(ref.error) << text;
    }
  }
  EXPECT_GT(parsed, 300);  // every outcome well exercised
  EXPECT_GT(refused, 300);
  EXPECT_GT(text_columns, 300);
}
