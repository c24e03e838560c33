// A robot's logs have text columns (a frame name, a status, a missing value):
// a problem reads such a table as long as nothing it states reads those
// columns, and gives the same sets as without them; every place that reads a
// column refuses a text one at its place in the problem file, naming the
// table's first cell that is not a number.
#include <gtest/gtest.h>

#include <fstream>

#include "data_tables.h"
#include "problem_text.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;
using namespace problem_test;

namespace {

// Ranges joined to their beacons, and the odometry as slices: the same
// problem on the plain tables and on the logs.
std::string ranges_problem(bool logs) {
  const std::string s = logs ? "_log.csv" : ".csv";
  return "[time]\ndomain = [0, 2]\ndelta = 0.1\n" + table("beacons", "beacons" + s) + table("ranges", "ranges" + s) +
         "[var.p]\nkind = \"tube_vector\"\ndim = 2\nvalue = [\"[-20, 20]\", \"[-20, 20]\"]\n"
         "[var.v]\nkind = \"tube_vector\"\ndim = 2\nvalue = [\"[-1, 1]\", \"[-1, 1]\"]\n"
         "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\njoin = { data = \"beacons\", on = \"id\" }\n"
         "y = \"p\"\nv = \"v\"\ntime = \"t\"\nwhere = { r = 9 }\n"
         "expr = \"sqrt((p[0] - bx)^2 + (p[1] - by)^2) - r + [-0.1, 0.1]\"\n"
         "[output]\nlandmarks = { data = \"beacons\", columns = [\"bx\", \"by\"] }\n";
}

std::string odometry_problem(bool logs) {
  const std::string s = logs ? "_log.csv" : ".csv";
  return table("stamps", "stamps" + s) + table("odo", "odo" + s) +
         "[time]\npoints = { data = \"stamps\", column = \"t\" }\n"
         "[var.d]\nkind = \"tube\"\nslices = { data = \"odo\", value = \"d/dt + [-0.01, 0.01]\" }\n"
         "[var.x]\nkind = \"tube\"\nat = [{ t = 0, value = 0 }]\n"
         "gates = { data = \"stamps\", value = \"t + [-0.5, 0.5]\" }\n"
         "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"d\"\n";
}

void expect_same_tubes(const SolveResult& a, const SolveResult& b, const std::string& var) {
  const TubeVector &x = *a.built.var(var).tubes, &y = *b.built.var(var).tubes;
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    ASSERT_EQ(x[i].nb_slices(), y[i].nb_slices());
    for (std::size_t k = 0; k < x[i].nb_slices(); ++k) EXPECT_EQ(x[i].slice(k), y[i].slice(k)) << var << " " << k;
    for (std::size_t k = 0; k <= x[i].nb_slices(); ++k) EXPECT_EQ(x[i].gate(k), y[i].gate(k)) << var << " " << k;
  }
}

}  // namespace

TEST(LoadTextColumns, UnreadTextColumnsChangeNothing) {
  for (const auto& make : {ranges_problem, odometry_problem}) {
    const SolveResult plain = solve_problem(parse(make(false)));
    const SolveResult logs = solve_problem(parse(make(true)));
    ASSERT_FALSE(plain.empty) << plain.why_empty;
    ASSERT_FALSE(logs.empty) << logs.why_empty;
    for (const auto& v : plain.built.vars) expect_same_tubes(plain, logs, v.spec->name);
  }
}

TEST(LoadTextColumns, ReadingATextColumnIsAnErrorAtItsPlace) {
  const std::string ranges = ranges_problem(true), odometry = odometry_problem(true);
  const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  const std::string odo_frame = "column 'frame' of table 'odo', which is not all numbers (" + data_dir() +
                                "/odo_log.csv:2: column 'frame': 'base_link' is not a finite number), expected a "
                                "column of finite numbers";
  // The value of slices from a table.
  expect_error(replaced(odometry, "d/dt + [-0.01, 0.01]", "d/dt + frame"), "test.toml:9:35: found the " + odo_frame);
  // A column listed by [data.NAME] columns.
  expect_error(replaced(odometry, "odo_log.csv\"\n", "odo_log.csv\"\ncolumns = [\"d\", \"frame\"]\n"),
               "found the " + odo_frame);
  // [time] points.
  expect_error(replaced(odometry, "column = \"t\"", "column = \"label\""),
               "found the column 'label' of table 'stamps', which is not all numbers (" + data_dir() +
                   "/stamps_log.csv:2: column 'label': 'start' is not a finite number)");
  // The value of gates from a table.
  expect_error(replaced(odometry, "\"t + [-0.5, 0.5]\"", "\"label\""), "found the column 'label' of table 'stamps'");
  // An eval's observation (a joined table's column), time, where and join columns.
  expect_error(replaced(ranges, "- r + [-0.1, 0.1]", "- r + name"),
               "found the column 'name' of table 'beacons', which is not all numbers (" + data_dir() +
                   "/beacons_log.csv:2: column 'name': 'north gate' is not a finite number)");
  expect_error(replaced(ranges, "- r + [-0.1, 0.1]", "- r + status"),
               "found the column 'status' of table 'ranges', which is not all numbers (" + data_dir() +
                   "/ranges_log.csv:2: column 'status': 'ok' is not a finite number)");
  expect_error(replaced(ranges, "time = \"t\"", "time = \"status\""), "found the column 'status' of table 'ranges'");
  expect_error(replaced(ranges, "where = { r = 9 }", "where = { status = 9 }"),
               "found the column 'status' of table 'ranges'");
  expect_error(replaced(ranges, "columns = [\"bx\", \"by\"]", "columns = [\"bx\", \"name\"]"),
               "found the column 'name' of table 'beacons'");
  // The truth to check.
  expect_error(odometry + "[output]\ntruth = { data = \"odo\", time = \"d\", columns = { x = \"frame\" } }\n",
               "found the " + odo_frame);
  // A problem that reads no text column solves, as above; one cell of a column read, made text, is named.
  std::ofstream(data_dir() + "/odo_bad.csv") << "d,frame,h\n0.5,base_link,0.1\n1x,base_link,0.2\n0.5,odom,0.3\n";
  expect_error(replaced(odometry, "odo_log.csv", "odo_bad.csv"),
               "found the column 'd' of table 'odo', which is not all numbers (" + data_dir() +
                   "/odo_bad.csv:3: column 'd': '1x' is not a finite number)");
}
