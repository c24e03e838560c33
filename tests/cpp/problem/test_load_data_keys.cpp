// Keys that tie a problem to its data tables: [time] points (the stamps of a
// table), tubes whose slices or gates come from a table, the heading constraint
// (CtcHeading), eval rows joined to another table, and ${VAR:-default} in
// data paths. What they build, and their errors at their place.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "data_tables.h"
#include "problem_text.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;
using problem_test::data_dir;
using problem_test::expect_error;
using problem_test::parse;
using problem_test::table;

namespace {

const std::string kStamps = "[time]\npoints = { data = \"stamps\", column = \"t\" }\n";  // line 2 after the tables

}  // namespace

TEST(LoadDataKeys, TimePointsAndSlicesFromTables) {
  const Problem p = parse(table("stamps", "stamps.csv") + table("odo", "odo.csv") + kStamps +
                          "[var.d]\nkind = \"tube\"\nslices = { data = \"odo\", value = \"d/dt + [-0.01, 0.01]\" }\n"
                          "[var.x]\nkind = \"tube\"\nat = [{ t = 0, value = 0 }]\n"
                          "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"d\"\n");
  EXPECT_EQ(p.time.points, (std::vector<double>{0, 0.5, 1.5, 2}));
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty);
  const Tube& d = (*r.built.var("d").tubes)[0];
  ASSERT_EQ(d.nb_slices(), 3u);
  EXPECT_TRUE(d.slice(0).contains(1.0) && d.slice(1).contains(1.0) && d.slice(2).contains(1.0));
  EXPECT_LT(d.slice(1).diam(), 0.03);
  EXPECT_TRUE(d.gate(1).contains(1.0));  // the hull of the slices around it
  const Tube& x = (*r.built.var("x").tubes)[0];
  EXPECT_TRUE(x.gate(3).contains(2.0));  // x' = 1 over [0, 2]
  EXPECT_LT(x.gate(3).diam(), 0.05);
  // A delta for time points from data is an error of the option, not ignored nor blamed on the file.
  const auto error_of_options = [&](const SolveOptions& o, const std::string& prefix) {
    try {
      check_solve_options(p, o, prefix);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  SolveOptions o;
  o.delta = 0.1;
  const std::string why = "expected no delta: the time points of this problem are the stamps of the table 'stamps' "
                          "([time] points at " + problem_test::problems_dir() + "/test.toml:6:10), one slice per period of the data";
  EXPECT_EQ(error_of_options(o, "--"), "--delta: found 0.1, " + why);
  EXPECT_THROW((void)solve_problem(p, o), Error);
  o.delta.reset();
  o.auto_delta = true;
  EXPECT_EQ(error_of_options(o, ""), "delta: found auto, " + why);
  o.auto_delta = false;
  o.refinement = DeltaRefinement::Regions;  // refines an automatic delta only
  EXPECT_EQ(error_of_options(o, "--"), "--refine: found regions, expected it with an automatic delta (--delta auto, "
                                       "or delta = \"auto\" in [time]): a fixed delta is not refined");
}

TEST(LoadDataKeys, TimePointsErrors) {
  expect_error(table("stamps", "stamps.csv") + "[time]\npoints = { data = \"stamps\", column = \"t\" }\ndelta = 0.1\n",
               "found 'delta' with 'points', expected either points = {data, column} or domain and delta");
  expect_error(table("odo", "odo.csv") + "[time]\npoints = { data = \"odo\", column = \"d\" }\n",
               "found the stamps 1 at " + data_dir() + "/odo.csv:3 and 0.5 at line 4 of 'odo', not increasing, "
               "expected strictly increasing time points");
  expect_error(table("stamps", "stamps.csv") + "[time]\npoints = { data = \"stamps\", column = \"u\" }\n",
               "test.toml:4:38: found the column 'u' missing from table 'stamps'");
  expect_error(table("stamps", "stamps.csv") + table("beacons", "beacons.csv") + kStamps +
                   "[var.d]\nkind = \"tube\"\nslices = { data = \"beacons\", value = \"bx\" }\n",
               "found the table 'beacons' of 2 rows, expected one row per slice: 3 rows");
  expect_error("[time]\ndomain = [0, 1]\ndelta = 0.1\n" + table("odo", "odo.csv") +
                   "[var.d]\nkind = \"tube\"\nslices = { data = \"odo\", value = \"d\" }\n",
               "found 'slices' without time points from data, expected [time] points = {data, column}");
  expect_error(table("stamps", "stamps.csv") + table("odo", "odo.csv") + kStamps +
                   "[var.d]\nkind = \"tube\"\nslices = { data = \"odo\", value = \"d + q\" }\n",
               "expected an expression of the columns of 'odo' and dt");
}

// gates = {data, value}: the value at each time point from its row (a
// position measured at each stamp), the slices left to the constraints.
TEST(LoadDataKeys, GatesFromATable) {
  const std::string head = table("stamps", "stamps.csv") + table("odo", "odo.csv") + kStamps;
  const Problem p = parse(head + "[var.x]\nkind = \"tube\"\ngates = { data = \"stamps\", value = \"t + [-0.01, 0.01]\" }\n"
                                 "[var.d]\nkind = \"tube\"\nslices = { data = \"odo\", value = \"d/dt + [-0.5, 0.5]\" }\n"
                                 "[[constraint]]\nkind = \"deriv\"\nx = \"x\"\nv = \"d\"\n");
  ASSERT_TRUE(p.var("x")->gates);
  EXPECT_EQ(p.var("x")->gates->data, "stamps");
  const BuiltProblem b = build_network(p, 0.5);
  EXPECT_TRUE((*b.var("x").tubes)[0].slice(1).is_unbounded());  // the slices are the constraints' to contract
  EXPECT_EQ(b.value_nodes.size(), 1u);  // the values at the stamps as written: one CtcEvalList
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  const Tube& x = (*r.built.var("x").tubes)[0];
  const std::vector<double> stamps{0, 0.5, 1.5, 2};
  for (std::size_t k = 0; k < 4; ++k) {  // within an ulp of a stamp times |x'| <= 1.5 of the row's value
    EXPECT_TRUE(x.gate(k).contains(stamps[k])) << k;
    EXPECT_TRUE(x.gate(k).is_subset(Interval(stamps[k] - 0.0100001, stamps[k] + 0.0100001))) << x.gate(k);
  }
  EXPECT_TRUE(x.slice(1).contains(1.0));  // x(t) = t, between its gates 0.5 and 1.5 with x' in [0.5, 1.5]
  EXPECT_LT(x.slice(1).diam(), 1.1);

  expect_error(head + "[var.x]\nkind = \"tube\"\ngates = { data = \"odo\", value = \"d\" }\n",
               "found the table 'odo' of 3 rows, expected one row per time point: 4 rows");
  expect_error(head + "[var.x]\nkind = \"tube\"\ngates = { data = \"stamps\", value = \"t + dt\" }\n",
               "expected an expression of the columns of 'stamps'");
  expect_error(head + "[var.x]\nkind = \"tube_vector\"\ndim = 2\ngates = { data = \"stamps\", value = \"t\" }\n",
               "found 'gates' for the tube_vector 'x', expected 'gates' on a tube");
  expect_error("[time]\ndomain = [0, 1]\ndelta = 0.1\n" + table("odo", "odo.csv") +
                   "[var.d]\nkind = \"tube\"\ngates = { data = \"odo\", value = \"d\" }\n",
               "test.toml:8:9: found 'gates' without time points from data, expected [time] points = {data, column}");
  expect_error(head + "[var.x]\nkind = \"tube\"\ngates = { data = \"stamps\", value = \"t\", column = \"t\" }\n",
               "found the unknown key 'column' in the gates of x");
}

TEST(LoadDataKeys, HeadingConstraint) {
  const std::string vars = "[var.p]\nkind = \"tube_vector\"\ndim = 2\nat = [{ t = 0, value = [0, 0] }]\n"
                           "[var.psi]\nkind = \"tube\"\nvalue = \"[-0.01, 0.01]\"\n"
                           "[var.d]\nkind = \"tube\"\nslices = { data = \"odo\", value = \"d + [-0.01, 0.01]\" }\n"
                           "[var.w]\nkind = \"tube\"\nvalue = \"[-0.1, 0.1]\"\n";
  const std::string head = table("stamps", "stamps.csv") + table("odo", "odo.csv") + kStamps + vars;
  const SolveResult r = solve_problem(parse(head + "[[constraint]]\nkind = \"heading\"\np = \"p\"\npsi = \"psi\"\n"
                                               "dist = \"d\"\nomega = \"w\"\ntrack = 0.01\n"));
  ASSERT_FALSE(r.empty) << r.why_empty;
  const TubeVector& p = *r.built.var("p").tubes;
  // Heading about 0: the robot goes east by 0.5 + 1 + 0.5 = 2 (each ± 0.01).
  EXPECT_TRUE(p[0].gate(3).contains(2.0));
  EXPECT_LT(p[0].gate(3).diam(), 0.1);
  EXPECT_LT(p[1].gate(3).diam(), 0.1);
  expect_error(head + "[[constraint]]\nkind = \"heading\"\np = \"psi\"\npsi = \"psi\"\ndist = \"d\"\nomega = \"w\"\n",
               "found 'psi' (tube, dim 1), expected a position: a tube_vector of dim 2");
  expect_error(head + "[[constraint]]\nkind = \"heading\"\np = \"p\"\npsi = \"p\"\ndist = \"d\"\nomega = \"w\"\n",
               "found the tube_vector 'p', expected a scalar tube");
}

// The ranges (t, id, r) joined to the beacons (id, bx, by): row 2's id 9 has
// no beacon, an error naming the row; without it the robot is localised.
TEST(LoadDataKeys, EvalRowsJoinedToAnotherTable) {
  const std::string head = "[time]\ndomain = [0, 2]\ndelta = 0.1\n" + table("beacons", "beacons.csv") +
                           table("ranges", "ranges.csv") +
                           "[var.p]\nkind = \"tube_vector\"\ndim = 2\nvalue = [\"[-20, 20]\", \"[-20, 20]\"]\n"
                           "[var.v]\nkind = \"tube_vector\"\ndim = 2\nvalue = [\"[-1, 1]\", \"[-1, 1]\"]\n"
                           "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\njoin = { data = \"beacons\", on = \"id\" }\n"
                           "y = \"p\"\nv = \"v\"\ntime = \"t\"\n";
  const std::string obs = "expr = \"sqrt((p[0] - bx)^2 + (p[1] - by)^2) - r + [-0.1, 0.1]\"\n";
  std::string msg;
  try {
    (void)solve_problem(parse(head + obs));
  } catch (const ProblemError& e) {
    msg = e.what();
  }
  // Found by the loader, so that sillage check says it: the row's line, the join's place.
  EXPECT_NE(msg.find("test.toml:19:8: found the row of 'ranges' at " + data_dir() +
                     "/ranges.csv:4 with id = 9, which is in no row of 'beacons', expected a row of 'beacons' with "
                     "that id ('where' leaves rows out)"),
            std::string::npos)
      << msg;
  const SolveResult r = solve_problem(parse(head + "where = { r = 9 }\n" + obs));
  ASSERT_FALSE(r.empty);
  const TubeVector& p = *r.built.var("p").tubes;
  // At t = 1 (a cell: 1 ± an ulp, so across gate 10) the robot is 9 ± 0.1
  // from (10, 0): x >= 0.9 then, and >= 0.9 - 0.1 (|x'| <= 1 over a slice) at the gate.
  EXPECT_GE(p[0].gate(10).lb(), 0.8 - 1e-9);
  EXPECT_LT(p[0].gate(5).lb(), 0.8);
  expect_error(head + "where = { r = 9 }\n" + obs + "", "");  // valid: no error
  expect_error(table("beacons", "beacons.csv") + table("ranges", "ranges.csv") + "[time]\ndomain = [0, 2]\ndelta = 0.1\n" +
                   "[var.p]\nkind = \"tube_vector\"\ndim = 2\n[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\n"
                   "join = { data = \"beacons\", on = \"r\" }\ny = \"p\"\n" + obs,
               "found the column 'r', expected a column of both 'ranges' and 'beacons'");
}

// A key listed twice in the joined table with other values: which row a
// range joins would decide the answer (one order solved, the other did not).
// Refused, naming both lines; the same row twice is harmless.
TEST(LoadDataKeys, AJoinKeyTwiceIsRefused) {
  const std::string dir = data_dir();
  std::ofstream(dir + "/beacons_twice.csv") << "id,bx,by\n3,10,0\n7,0,10\n3,-10,0\n";
  std::ofstream(dir + "/beacons_same_twice.csv") << "id,bx,by\n3,10,0\n7,0,10\n3,10,0\n";
  const auto problem = [](const std::string& beacons) {
    return "[time]\ndomain = [0, 2]\ndelta = 0.1\n" + table("beacons", beacons) + table("ranges", "ranges.csv") +
           "[var.p]\nkind = \"tube_vector\"\ndim = 2\n[var.v]\nkind = \"tube_vector\"\ndim = 2\n"
           "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\njoin = { data = \"beacons\", on = \"id\" }\n"
           "y = \"p\"\nv = \"v\"\ntime = \"t\"\nwhere = { r = 9 }\n"
           "expr = \"sqrt((p[0] - bx)^2 + (p[1] - by)^2) - r + [-0.1, 0.1]\"\n";
  };
  expect_error(problem("beacons_twice.csv"), "found the id 3 in two rows of 'beacons' with other values: " + dir +
                                                 "/beacons_twice.csv:2 and line 4, expected one row per id in the joined table");
  expect_error(problem("beacons_same_twice.csv"), "");  // valid
}

// The hash is of the problem's inputs: its text and the numbers of its tables.
TEST(LoadDataKeys, TheHashCoversTheData) {
  const std::string dir = data_dir();
  std::ofstream(dir + "/hash_a.csv") << "t,x\n0,1\n1,2\n";
  std::ofstream(dir + "/hash_b.csv") << "t,x\n0,1\n1,2.5\n";
  std::ofstream(dir + "/hash_c.csv") << "# the same numbers, written otherwise\nt, x\n0.0, 1e0\n1, 2\n";
  const auto hash = [&](const std::string& file) {
    std::ofstream(dir + "/hash.csv") << problem_test::read_file(dir + "/" + file);
    return parse(table("d", "hash.csv") + "[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = \"tube\"\n"
                 "[[constraint]]\nkind = \"expr\"\nexpr = \"x\"\n").hash;
  };
  EXPECT_NE(hash("hash_a.csv"), hash("hash_b.csv"));
  EXPECT_EQ(hash("hash_a.csv"), hash("hash_c.csv"));
}

TEST(LoadDataKeys, EnvironmentInDataPaths) {
  ::setenv("SILLAGE_TEST_DIR", data_dir().c_str(), 1);
  const Problem p = parse("[data.s]\nfile = \"${SILLAGE_TEST_DIR}/stamps.csv\"\n" + kStamps.substr(0, 7) +
                          "points = { data = \"s\", column = \"t\" }\n[var.x]\nkind = \"tube\"\n"
                          "[[constraint]]\nkind = \"expr\"\nexpr = \"x\"\n");
  EXPECT_EQ(p.time.points.size(), 4u);
  ::unsetenv("SILLAGE_TEST_DIR");
  expect_error("[data.s]\nfile = \"${SILLAGE_TEST_DIR}/stamps.csv\"\n", "test.toml:2:8: found the environment variable SILLAGE_TEST_DIR unset");
  expect_error("[data.s]\nfile = \"${SILLAGE_TEST_DIR:-" + data_dir() + "}/nothing.csv\"\n", data_dir() + "/nothing.csv");
  expect_error("[data.s]\nfile = \"${SILLAGE_TEST_DIR/stamps.csv\"\n", "found an unclosed ${");
}

TEST(LoadDataKeys, LandmarksOnTheMaps) {
  const std::string head = "[time]\ndomain = [0, 2]\ndelta = 0.5\n" + table("beacons", "beacons.csv") +
                           "[var.p]\nkind = \"tube_vector\"\ndim = 2\nvalue = [\"[-1, 12]\", \"[-1, 12]\"]\n"
                           "[[constraint]]\nkind = \"expr\"\nexpr = \"p[0] - p[1]\"\n[output]\n";
  const Problem p = parse(head + "landmarks = { data = \"beacons\", columns = [\"bx\", \"by\"] }\n");
  ASSERT_TRUE(p.output.landmarks);
  EXPECT_EQ(p.output.landmarks->x, "bx");
  expect_error(head + "landmarks = { data = \"beacons\", columns = [\"bx\", \"bz\"] }\n",
               "found the column 'bz' missing from table 'beacons'");
  expect_error(head + "landmarks = { data = \"beacons\", columns = [\"bx\"] }\n",
               "found an array of 1 element(s), expected two columns [\"x\", \"y\"]");
}

// [network] order = "cost": the same fixed point (ratio 0), constraints
// entering the network cheap first; an emptiness still names the constraint
// of the file that found it.
TEST(LoadDataKeys, CostOrderSameFixedPoint) {
  std::string text = problem_test::read_file(problem_test::problems_dir() + "/drifting_clock.toml");
  Problem file = parse(text);
  Problem cost = file;
  cost.network.order = ConstraintOrder::Cost;
  const std::vector<std::size_t> order = constraint_order(cost);
  EXPECT_EQ(order.front(), 5u);  // the eval first
  const SolveResult a = solve_problem(file), b = solve_problem(cost);
  ASSERT_FALSE(a.empty || b.empty);
  for (const char* v : {"h", "y", "w"}) {
    const Tube &ta = (*a.built.var(v).tubes)[0], &tb = (*b.built.var(v).tubes)[0];
    for (std::size_t k = 0; k < ta.nb_slices(); ++k) ASSERT_EQ(ta.slice(k), tb.slice(k)) << v << " slice " << k;
  }
  expect_error(text.replace(text.find("ratio = 0"), 9, "ratio = 0\norder = \"fast\""),
               "found a string \"fast\", expected \"file\" or \"cost\"");
  text = problem_test::read_file(problem_test::problems_dir() + "/line_ranges.toml");
  text.replace(text.find("value = \"[-10, 10]\""), 19, "value = \"[5, 10]\"");
  Problem bad = parse(text + "[network]\norder = \"cost\"\n");
  const SolveResult e = solve_problem(bad);
  ASSERT_TRUE(e.empty);
  EXPECT_NE(e.why_empty.find("constraint"), std::string::npos) << e.why_empty;
}
