// CsvTable: parsing, column access, errors that name file, line and column,
// and the real datasets of ../shared/data when present.
#include <gtest/gtest.h>

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

TEST(Csv, ErrorsSayWhere) {
  try {
    CsvTable::parse("a,b\n1,2\n3,x\n", "f.csv");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("f.csv:3: column 'b': 'x'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(CsvTable::parse("a,b\n1\n", "f.csv"), ParseError);
  EXPECT_THROW(CsvTable::parse("a\nnan\n", "f.csv"), ParseError);
  EXPECT_THROW(CsvTable::parse("", "f.csv"), ParseError);
  EXPECT_THROW(CsvTable::read("/nonexistent/file.csv"), Error);
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
