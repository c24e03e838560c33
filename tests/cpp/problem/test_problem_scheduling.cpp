// The network's scheduling (cn/scheduling.h) on the example problems: FIFO
// and by expected contraction over cost reach the same fixed point with the
// wake ratio 0 (the true fixed point): bit for bit, up to a few ulps where a
// contractor is not inclusion-monotone to the last ulp (the drifting clock
// since its ephemeris tubes come from the batch sin/cos rows). The
// contractor runs of both are compared in bench/bench_problem.cpp
// (BM_Schedule, docs/cli.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

#include "kit/close_bounds.h"
#include "problem_text.h"
#include "sillage/problem/check_summary.h"
#include "sillage/problem/report_html.h"
#include "sillage/problem/solve_problem.h"
#include "sillage/problem/write_results.h"

using namespace sillage;

namespace {

BuiltProblem fixed_point(const std::string& name, Scheduling s, ContractStats& stats) {
  Problem p = load_problem(problem_test::problems_dir() + "/" + name);
  p.network.ratio = 0.0;
  BuiltProblem b = build_network(p, *p.time.delta);
  b.cn->set_scheduling(s);
  stats = b.cn->contract();
  return b;
}

constexpr std::uint64_t kUlps = 4;

using test::ulps_between;

}  // namespace

TEST(ProblemScheduling, SameFixedPointAsFifo) {
  for (const char* name : {"dead_reckoning.toml", "causal_chain.toml", "line_ranges.toml", "kidnapped_robot.toml",
                           "drifting_clock.toml"}) {
    ContractStats fs, ps;
    std::uint64_t worst = 0;
    std::size_t differ = 0;
    const BuiltProblem fifo = fixed_point(name, Scheduling::Fifo, fs);
    const BuiltProblem prio = fixed_point(name, Scheduling::Priority, ps);
    ASSERT_FALSE(fs.empty || ps.empty) << name;
    for (std::size_t v = 0; v < fifo.vars.size(); ++v) {
      const VarDomain &a = fifo.vars[v], &b = prio.vars[v];
      if (a.interval) { EXPECT_EQ(*a.interval, *b.interval) << name; }
      if (a.box) { EXPECT_EQ(*a.box, *b.box) << name; }
      if (!a.tubes) continue;
      for (std::size_t i = 0; i < a.tubes->size(); ++i) {
        const Tube &x = (*a.tubes)[i], &y = (*b.tubes)[i];
        ASSERT_EQ(x.nb_slices(), y.nb_slices());
        for (std::size_t k = 0; k < x.nb_slices(); ++k) {
          ASSERT_LE(ulps_between(x.slice(k), y.slice(k)), kUlps) << name << " " << a.spec->name << "[" << i << "] slice " << k
                                                         << ": " << x.slice(k) << " vs " << y.slice(k);
          ASSERT_LE(ulps_between(x.gate(k), y.gate(k)), kUlps) << name << " " << a.spec->name << "[" << i << "] gate " << k
                                                       << ": " << x.gate(k) << " vs " << y.gate(k);
          worst = std::max({worst, ulps_between(x.slice(k), y.slice(k)), ulps_between(x.gate(k), y.gate(k))});
          differ += x.slice(k) != y.slice(k) ? 1 : 0;
        }
      }
    }
    std::printf("%s, ratio 0: FIFO %zu runs, priority %zu runs; %zu slices differ, by %llu ulp(s) at most\n", name,
                fs.contractor_calls, ps.contractor_calls, differ, static_cast<unsigned long long>(worst));
  }
}

// [network] scheduling = "fifo" | "priority": read, given to the network,
// overridden by SolveOptions::scheduling (`sillage solve --scheduling`), and
// reported in results.json and report.html; the same fixed point as FIFO.
TEST(ProblemScheduling, FileKeyReachesTheNetworkAndTheReports) {
  // The drifting clock (its [network] has ratio = 0): there the two orders take different runs.
  const std::string text = problem_test::read_file(problem_test::problems_dir() + "/drifting_clock.toml");
  const auto with = [&](const std::string& key) {
    const std::string section = "[network]\n";
    std::string t = text;
    return t.insert(t.find(section) + section.size(), key);
  };
  const Problem fifo = problem_test::parse(text);
  const Problem prio = problem_test::parse(with("scheduling = \"priority\"\n"));
  EXPECT_EQ(fifo.network.ratio, 0.0);
  EXPECT_EQ(fifo.network.scheduling, Scheduling::Fifo);
  EXPECT_EQ(prio.network.scheduling, Scheduling::Priority);
  EXPECT_EQ(problem_test::parse(with("scheduling = \"fifo\"\n")).network.scheduling, Scheduling::Fifo);
  EXPECT_EQ(build_network(prio, *prio.time.delta).cn->scheduling(), Scheduling::Priority);
  const SolveResult a = solve_problem(fifo), b = solve_problem(prio);
  ASSERT_FALSE(a.empty || b.empty);
  EXPECT_EQ(a.scheduling, Scheduling::Fifo);
  EXPECT_EQ(b.scheduling, Scheduling::Priority);
  for (std::size_t v = 0; v < a.built.vars.size(); ++v) {
    const VarDomain &x = a.built.vars[v], &y = b.built.vars[v];
    for (std::size_t i = 0; x.tubes && i < x.tubes->size(); ++i)
      for (std::size_t k = 0; k <= (*x.tubes)[i].nb_slices(); ++k) {
        ASSERT_LE(ulps_between((*x.tubes)[i].gate(k), (*y.tubes)[i].gate(k)), kUlps) << x.spec->name << " gate " << k;
        if (k < (*x.tubes)[i].nb_slices()) {
          ASSERT_LE(ulps_between((*x.tubes)[i].slice(k), (*y.tubes)[i].slice(k)), kUlps) << x.spec->name;
        }
      }
    if (x.interval) { EXPECT_EQ(*x.interval, *y.interval) << x.spec->name; }
    if (x.box) { EXPECT_EQ(*x.box, *y.box) << x.spec->name; }
  }
  EXPECT_NE(results_json(prio, b).find("\"scheduling\": \"priority\""), std::string::npos);
  EXPECT_NE(results_json(fifo, a).find("\"scheduling\": \"fifo\""), std::string::npos);
  EXPECT_NE(report_html(prio, b).find("<p id=\"scheduling\">Scheduling: priority"), std::string::npos);
  EXPECT_NE(check_summary(prio).find("priority scheduling"), std::string::npos);

  SolveOptions o;
  o.scheduling = Scheduling::Fifo;  // the option wins over the file
  const SolveResult c = solve_problem(prio, o);
  EXPECT_EQ(c.scheduling, Scheduling::Fifo);
  EXPECT_EQ(c.schedule.back().stats.contractor_calls, a.schedule.back().stats.contractor_calls);
  EXPECT_NE(b.schedule.back().stats.contractor_calls, a.schedule.back().stats.contractor_calls);  // 340 against 321
}

TEST(ProblemScheduling, FileKeyErrorsAtTheirPlace) {
  const std::string text = problem_test::read_file(problem_test::problems_dir() + "/causal_chain.toml");
  std::size_t lines = 0;
  for (char ch : text) lines += ch == '\n';
  const std::string line = "test.toml:" + std::to_string(lines + 2) + ":14: ";
  const std::string bad = problem_test::error_of(text + "[network]\nscheduling = \"lifo\"\n");
  EXPECT_NE(bad.find(line + "found a string \"lifo\", expected \"fifo\" or \"priority\""), std::string::npos) << bad;
  const std::string num = problem_test::error_of(text + "[network]\nscheduling = 1\n");
  EXPECT_NE(num.find(line + "found an integer 1, expected \"fifo\" or \"priority\""), std::string::npos) << num;
  const std::string key = problem_test::error_of(text + "[network]\nschedule = \"fifo\"\n");
  EXPECT_NE(key.find("test.toml:" + std::to_string(lines + 2) + ":1: found the unknown key 'schedule'"),
            std::string::npos) << key;
}
