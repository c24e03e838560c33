// The network's scheduling (cn/scheduling.h) on the example problems: FIFO
// and by expected contraction over cost reach the same fixed point, bit for
// bit, with the wake ratio 0 (the true fixed point). The contractor runs of
// both are compared in bench/bench_problem.cpp (BM_Schedule, docs/cli.md).
#include <gtest/gtest.h>

#include "problem_text.h"
#include "sillage/problem/solve_problem.h"

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

}  // namespace

TEST(ProblemScheduling, SameFixedPointAsFifo) {
  for (const char* name : {"dead_reckoning.toml", "causal_chain.toml", "line_ranges.toml", "kidnapped_robot.toml",
                           "drifting_clock.toml"}) {
    ContractStats fs, ps;
    const BuiltProblem fifo = fixed_point(name, Scheduling::Fifo, fs);
    const BuiltProblem prio = fixed_point(name, Scheduling::Priority, ps);
    ASSERT_FALSE(fs.empty || ps.empty) << name;
    for (std::size_t v = 0; v < fifo.vars.size(); ++v) {
      const VarDomain &a = fifo.vars[v], &b = prio.vars[v];
      if (a.interval) EXPECT_EQ(*a.interval, *b.interval) << name;
      if (a.box) EXPECT_EQ(*a.box, *b.box) << name;
      if (!a.tubes) continue;
      for (std::size_t i = 0; i < a.tubes->size(); ++i) {
        const Tube &x = (*a.tubes)[i], &y = (*b.tubes)[i];
        ASSERT_EQ(x.nb_slices(), y.nb_slices());
        for (std::size_t k = 0; k < x.nb_slices(); ++k) {
          ASSERT_EQ(x.slice(k), y.slice(k)) << name << " " << a.spec->name << "[" << i << "] slice " << k;
          ASSERT_EQ(x.gate(k), y.gate(k)) << name << " " << a.spec->name << "[" << i << "] gate " << k;
        }
      }
    }
    std::printf("%s, ratio 0: FIFO %zu runs, priority %zu runs\n", name, fs.contractor_calls, ps.contractor_calls);
  }
}
