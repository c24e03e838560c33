// OnlineProblem and replay_problem: a problem file run online (docs/online.md,
// "From a problem file"). The shipped examples replayed (the truth never
// outside; with W infinite the batch box inside the online one), the order
// rows arrive in, and every refusal with nothing changed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>
#include <unistd.h>

#include "problem_text.h"
#include "sillage/error.h"
#include "sillage/problem/online_problem.h"
#include "sillage/problem/replay_problem.h"
#include "sillage/problem/stream_lines.h"

using namespace sillage;

namespace {

// A robot in the plane: p' = v with |v| <= 2, p(0) in [-1, 1]^2, the distance
// driven per period from odometry, ranges to two beacons stamped +- 0.1 s.
std::string robot_text() {
  static const std::string dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("sillage_online_problem_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::ofstream(d / "stamps.csv") << "t\n0\n0.5\n1\n1.5\n2\n2.5\n3\n";
    std::ofstream(d / "odo.csv") << "d,unused\n0.5,1\n0.5,1\n0.5,1\n0.5,1\n0.5,1\n0.5,1\n";
    std::ofstream(d / "beacons.csv") << "id,bx,by\n3,10,0\n7,0,10\n";
    // The robot drives p(t) = (t, 0): ranges |p(t) - beacon| at their stamps.
    std::ofstream(d / "ranges.csv") << "t,id,r\n0.7,3,9.3\n0.9,7,10.04\n1.6,3,8.4\n2.2,7,10.24\n2.95,3,7.05\n";
    return d.string();
  }();
  return "[time]\npoints = { data = \"stamps\", column = \"t\" }\n"
         "[network]\nratio = 0\n"
         "[data.stamps]\nfile = \"" + dir + "/stamps.csv\"\n"
         "[data.odo]\nfile = \"" + dir + "/odo.csv\"\ncolumns = [\"d\"]\n"
         "[data.beacons]\nfile = \"" + dir + "/beacons.csv\"\n"
         "[data.ranges]\nfile = \"" + dir + "/ranges.csv\"\n"
         "[var.p]\nkind = \"tube_vector\"\ndim = 2\nat = [{ t = 0, value = [\"[-1, 1]\", \"[-1, 1]\"] }]\n"
         "[var.v]\nkind = \"tube_vector\"\ndim = 2\nvalue = [\"[-2, 2]\", \"[-2, 2]\"]\n"
         "[var.dist]\nkind = \"tube\"\nslices = { data = \"odo\", value = \"d*[0.9, 1.1]\" }\n"
         "[var.speed]\nkind = \"tube\"\nvalue = \"[0, 2]\"\n"
         "[[constraint]]\nkind = \"deriv\"\nx = \"p\"\nv = \"v\"\n"
         "[[constraint]]\nkind = \"expr\"\nexpr = \"speed^2 - v[0]^2 - v[1]^2\"\n"
         "[[constraint]]\nkind = \"eval\"\ndata = \"ranges\"\njoin = { data = \"beacons\", on = \"id\" }\n"
         "y = \"p\"\nv = \"v\"\ntime = \"t\"\ntime_error = 0.1\n"
         "expr = \"sqrt((p[0] - bx)^2 + (p[1] - by)^2) - r + [-0.05, 0.05]\"\n"
         "[output]\nmaps = [[\"p[0]\", \"p[1]\"]]\n";
}

Problem robot() { return problem_test::parse(robot_text()); }

Problem example(const std::string& name) { return load_problem(problem_test::problems_dir() + "/" + name); }

// The message of the Error feed(row) raises; "" if none.
std::string refusal(OnlineProblem& op, const StreamRow& row) {
  try {
    op.feed(row);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(OnlineProblem, RecordedRowsComeInStampOrderAfterTheirClockRow) {
  const Problem p = robot();
  OnlineProblem op(p);
  const std::vector<StreamRow> rows = op.recorded_rows();
  ASSERT_EQ(rows.size(), 6u + 5u);
  std::vector<std::string> order;
  for (const StreamRow& r : rows) {
    char t[32];
    std::snprintf(t, sizeof t, "%g", *r.t);
    order.push_back(r.table + "@" + t);
  }
  const std::vector<std::string> expected = {"odo@0.5",    "odo@1",       "ranges@0.7", "ranges@0.9",
                                             "odo@1.5",    "odo@2",       "ranges@1.6", "odo@2.5",
                                             "ranges@2.2", "odo@3",       "ranges@2.95"};
  EXPECT_EQ(order, expected);
  EXPECT_EQ(rows[0].columns.at("d"), 0.5);
  EXPECT_EQ(op.outputs(), std::vector<std::string>{"p"});
}

TEST(OnlineProblem, ReplayHoldsTheTruthAndTheBatchBox) {
  const Problem p = robot();
  const ReplayResult r = replay_problem(p);
  EXPECT_EQ(r.summary.status, Status::Converged);
  EXPECT_TRUE(r.refused.empty()) << r.refused.front();
  ASSERT_GE(r.t.size(), 6u);  // each advance, and the ranges applied after their clock row
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const IntervalVector& x = r.online[k][0];
    EXPECT_TRUE(x[0].contains(r.t[k]) && x[1].contains(0)) << "t = " << r.t[k] << ": " << x;  // p(t) = (t, 0)
  }
  // W infinite, the fixed point (ratio 0): the batch knows the future, online never knows more.
  EXPECT_EQ(r.online_holds_batch(), r.t.size());
  EXPECT_GE(r.mean_side_ratio(0), 1.0);
}

TEST(OnlineProblem, SameRowsInAnotherOrderGiveTheSameDomains) {
  const Problem p = robot();
  OnlineProblem a(p), b(p);
  const std::vector<StreamRow> rows = a.recorded_rows();
  for (const StreamRow& r : rows) a.feed(r);
  std::vector<StreamRow> clock, ranges;  // the ranges all late, the last first
  for (const StreamRow& r : rows) (r.table == "odo" ? clock : ranges).push_back(r);
  std::reverse(ranges.begin(), ranges.end());
  for (const StreamRow& r : clock) b.feed(r);
  for (StreamRow r : ranges) {
    r.t.reset();  // arrived now, at the end
    b.feed(r);
  }
  const TubeVector& xa = *a.estimator().tube("p");
  const TubeVector& xb = *b.estimator().tube("p");
  ASSERT_EQ(xa.nb_slices(), xb.nb_slices());
  for (std::size_t k = 0; k <= xa.nb_slices(); ++k) {
    for (std::size_t i = 0; i < 2; ++i) {
      const Interval ga = xa[i].gate(k), gb = xb[i].gate(k);
      const double slack = 1e-9 * std::max(1.0, ga.mag());
      EXPECT_TRUE(ga.is_subset(gb + Interval(-slack, slack)) && gb.is_subset(ga + Interval(-slack, slack)))
          << "gate " << k << " p[" << i << "]: " << ga << " vs " << gb;
    }
  }
}

TEST(OnlineProblem, ShippedExamplesNeverLoseTheTruth) {
  for (const std::string name : {"kidnapped_robot.toml", "drifting_clock.toml"}) {
    const Problem p = example(name);
    ReplayOptions o;
    o.batch = false;
    const ReplayResult r = replay_problem(p, o);
    EXPECT_EQ(r.summary.status, Status::Converged) << name;
    EXPECT_TRUE(r.truth_misses.empty()) << name << ": " << r.truth_misses.front();
    EXPECT_GT(r.truth_samples, 100u) << name;
    EXPECT_EQ(r.truth_inside + r.truth_unbounded, r.truth_samples) << name;
  }
}

TEST(OnlineProblem, KidnappedRobotIsUnknownUntilItsFix) {
  // Online, the position is unbounded until the fix at t = 37 (causal: the
  // batch solve bounds the past from it, the robot could not).
  const ReplayResult r = replay_problem(example("kidnapped_robot.toml"));
  ASSERT_FALSE(r.t.empty());
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const bool bounded = r.online[k][0][0].is_bounded();
    if (r.t[k] < 36.9) {
      EXPECT_FALSE(bounded) << "t = " << r.t[k];
    }
    if (r.t[k] > 37.1) {
      EXPECT_TRUE(bounded) << "t = " << r.t[k];
    }
  }
  EXPECT_EQ(r.online_holds_batch(), r.t.size());
}

TEST(OnlineProblem, RefusesBadRowsWithNothingChanged) {
  const Problem p = robot();
  OnlineProblem op(p);
  op.feed({"odo", 0.5, {{"d", 0.5}}});
  const double now = op.estimator().now();
  const std::size_t updates = op.estimator().stats().updates;
  const auto refused = [&](const StreamRow& row, const std::string& what) {
    const std::string e = refusal(op, row);
    EXPECT_NE(e.find(what), std::string::npos) << "expected '" << what << "' in: " << e;
    EXPECT_EQ(op.estimator().now(), now);
    EXPECT_EQ(op.estimator().stats().updates, updates);
  };
  refused({"nope", 1.0, {}}, "no table nope");
  refused({"beacons", 1.0, {{"id", 3}, {"bx", 1}, {"by", 2}}}, "read by no online constraint");
  refused({"odo", 1.0, {{"d", 0.5}, {"typo", 1}}}, "no column typo");
  refused({"odo", 1.0, {{"unused", 1}}}, "without its column d");
  refused({"odo", 1.0, {{"d", std::nan("")}}}, "d is NaN");
  refused({"odo", std::nullopt, {{"d", 0.5}}}, "without \"t\"");
  refused({"odo", 0.5, {{"d", 0.5}}}, "not after now");
  refused({"odo", INFINITY, {{"d", 0.5}}}, "not finite");
  refused({"ranges", std::nullopt, {{"t", 0.3}, {"id", 5}, {"r", 9}}}, "id = 5 is in no row of beacons");
  refused({"ranges", std::nullopt, {{"t", 9}, {"id", 3}, {"r", 9}}}, "[online] lead");
  refused({"", 2.0, {}}, "not by a row of no table");
  EXPECT_EQ(op.waiting(), 0u);
  // Beyond now but within the lead: held, then applied once time reaches it.
  op.feed({"ranges", std::nullopt, {{"t", 0.7}, {"id", 3}, {"r", 9.3}}});
  EXPECT_EQ(op.waiting(), 1u);
  op.feed({"odo", 1.0, {{"d", 0.5}}});
  EXPECT_EQ(op.waiting(), 0u);
  EXPECT_EQ(op.estimator().pending(), 0u);  // [0.6, 0.8] is over by t = 1
  EXPECT_EQ(op.estimator().stats().observations, 1u);
}

TEST(OnlineProblem, RefusesAnObservationOlderThanTheWindow) {
  const Problem p = robot();
  OnlineOptions o = online_options(p);
  o.window = 0.5;
  o.forget_every = 0.1;
  OnlineProblem op(p, o);
  for (const double t : {0.5, 1.0, 1.5, 2.0}) op.feed({"odo", t, {{"d", 0.5}}});
  EXPECT_GT(op.estimator().window_start(), 0.7);
  EXPECT_NE(refusal(op, {"ranges", std::nullopt, {{"t", 0.7}, {"id", 3}, {"r", 9.3}}}).find("older than the window"),
            std::string::npos);
}

TEST(OnlineProblem, SaysWhatCannotRunOnline) {
  try {
    OnlineProblem op(example("temporal_slam.toml"));
    FAIL() << "p_implies_z ran online";
  } catch (const ProblemError& e) {
    EXPECT_NE(std::string(e.what()).find("the whole path"), std::string::npos) << e.what();
  }
  std::string text = robot_text();
  text.replace(text.find("[var.speed]"), 0, "[var.b]\nkind = \"interval\"\nvalue = \"[0, 1]\"\n");
  try {
    OnlineProblem op(problem_test::parse(text));
    FAIL() << "an interval variable ran online";
  } catch (const ProblemError& e) {
    EXPECT_NE(std::string(e.what()).find("a constant of the whole run"), std::string::npos) << e.what();
  }
}

TEST(OnlineProblem, OnlineSectionIsReadAndChecked) {
  const Problem p = problem_test::parse(robot_text() + "[online]\nwindow = 2\nlead = 1\noutputs = [\"p\", \"v\"]\n");
  EXPECT_EQ(*p.online.window, 2.0);
  EXPECT_EQ(p.online.lead, 1.0);
  EXPECT_EQ(online_options(p).window, 2.0);
  EXPECT_EQ(OnlineProblem(p).outputs(), (std::vector<std::string>{"p", "v"}));
  EXPECT_EQ(online_options(problem_test::parse(robot_text() + "[online]\nwindow = \"inf\"\n")).window, INFINITY);
  for (const std::string bad : {"window = 0", "lead = -1", "outputs = [\"nope\"]", "typo = 1"}) {
    EXPECT_THROW(problem_test::parse(robot_text() + "[online]\n" + bad + "\n"), ProblemError) << bad;
  }
}

TEST(StreamLines, ParsesRowsAndTicksAndSaysWhatIsWrong) {
  const StreamRow r = parse_stream_line(R"({"table": "ranges", "t": 1.5, "columns": {"t": 1.4, "id": 3, "r": 9}})");
  EXPECT_EQ(r.table, "ranges");
  EXPECT_EQ(*r.t, 1.5);
  EXPECT_EQ(r.columns.at("t"), 1.4);
  EXPECT_EQ(r.columns.at("id"), 3);
  const StreamRow tick = parse_stream_line(R"({"t": 2})");
  EXPECT_TRUE(tick.table.empty());
  EXPECT_EQ(*tick.t, 2.0);
  const auto error = [](const std::string& line) {
    try {
      parse_stream_line(line);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("nope").find("not JSON"), std::string::npos);
  EXPECT_NE(error("[1]").find("not an object"), std::string::npos);
  EXPECT_NE(error(R"({"table": 3})").find("not a table's name"), std::string::npos);
  EXPECT_NE(error(R"({"t": "x"})").find("not a number"), std::string::npos);
  EXPECT_NE(error(R"({"table": "a", "columns": {"c": null}})").find("column \"c\""), std::string::npos);
  EXPECT_NE(error(R"({"table": "a", "stamp": 1})").find("unknown key \"stamp\""), std::string::npos);
  EXPECT_NE(error(R"({})").find("an empty row"), std::string::npos);
}

TEST(StreamLines, EstimateLineGivesTheBoxesNow) {
  const Problem p = robot();
  OnlineProblem op(p);
  op.feed({"odo", 0.5, {{"d", 0.5}}});
  const std::string line = estimate_line(op);
  EXPECT_EQ(line.rfind(R"({"t":0.5,"status":"converged","window":[0.0,0.5],"p":[[)", 0), 0u) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
}

TEST(StreamLines, StreamLineReadsBackAsTheSameRow) {
  const StreamRow row{"ranges", 0.1, {{"t", 1.0 / 3}, {"id", 7}, {"r", -2.5e-300}}};
  const StreamRow back = parse_stream_line(stream_line(row));
  EXPECT_EQ(back.table, row.table);
  EXPECT_EQ(back.t, row.t);
  EXPECT_EQ(back.columns, row.columns);  // bit for bit
  EXPECT_EQ(stream_line(StreamRow{"", 2.0, {}}), R"({"t":2.0})");
}

// A replay is cancelled by its budget's token: before a row, or while it waits
// for a row's time at a given speed (then at once, not at the end of the log).
TEST(OnlineProblem, ReplayIsCancelledByItsToken) {
  const Problem p = example("drifting_clock.toml");
  ReplayOptions o;
  o.budget.cancel.cancel();
  EXPECT_THROW(replay_problem(p, o), Cancelled);
  ReplayOptions slow;
  slow.speed = 1.0;  // 13 s of log
  std::thread stopper([token = slow.budget.cancel] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    token.cancel();
  });
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(replay_problem(p, slow), Cancelled);
  stopper.join();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}
