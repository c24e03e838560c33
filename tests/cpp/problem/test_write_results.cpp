// results.json written as text (write_results.cpp): valid JSON whose bounds
// are the domains' doubles exactly; null for an infinite bound and for an
// empty interval; intervals and boxes as "value".
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "problem_text.h"
#include "sillage/problem/solve_problem.h"
#include "sillage/problem/write_results.h"

using namespace sillage;

TEST(WriteResults, BoundsExactlyNullsForInfinitiesAndEmpties) {
  const Problem p = problem_test::parse(
      "[time]\ndomain = [0, 1]\ndelta = 0.25\n"
      "[var.x]\nkind = \"tube\"\nvalue = \"[0, 1]/3\"\n"
      "[var.u]\nkind = \"tube\"\n"
      "[var.a]\nkind = \"interval\"\nvalue = \"[1, 2]\"\n"
      "[var.b]\nkind = \"box\"\ndim = 2\nvalue = [\"[0, 1]\", \"[2, 3]\"]\n"
      "[[constraint]]\nkind = \"expr\"\nexpr = \"a - 1.5 - 0*b[0]\"\n");
  SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  (*r.built.var("x").tubes)[0].set(Interval::empty(), 1);  // as a writer may meet it
  const std::string text = results_json(p, r);
  const auto j = nlohmann::json::parse(text);
  const Tube& x = (*r.built.var("x").tubes)[0];
  const auto& jx = j["variables"]["x"]["components"][0];
  ASSERT_EQ(jx["gates"].size(), x.nb_slices() + 1);
  for (std::size_t k = 0; k <= x.nb_slices(); ++k) {
    if (x.gate(k).is_empty()) {  // the gates of the emptied slice
      EXPECT_TRUE(jx["gates"][k].is_null()) << k;
      continue;
    }
    EXPECT_EQ(jx["gates"][k][0].get<double>(), x.gate(k).lb());
    EXPECT_EQ(jx["gates"][k][1].get<double>(), x.gate(k).ub());  // 1/3 rounded up, to the last bit
  }
  EXPECT_TRUE(jx["slices"][1].is_null());
  const auto& ju = j["variables"]["u"]["components"][0]["gates"][0];
  EXPECT_TRUE(ju[0].is_null() && ju[1].is_null());
  EXPECT_EQ(j["variables"]["a"]["kind"], "interval");
  EXPECT_EQ(j["variables"]["a"]["value"][0][0].get<double>(), 1.5);
  EXPECT_EQ(j["variables"]["b"]["dim"], 2);
  EXPECT_EQ(j["variables"]["b"]["value"][1][1].get<double>(), 3.0);
  EXPECT_EQ(j["status"], "solved");
}
