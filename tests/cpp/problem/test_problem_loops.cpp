// [output] loops: the t-plane of a problem's velocity tube (thesis ch. 6) on
// examples/problems/figure_eight.toml, whose one self-crossing is known
// exactly (t = pi/2 and 3 pi/2, at the origin); and the errors of the key.
#include <gtest/gtest.h>

#include <cmath>

#include "problem_text.h"
#include "sillage/problem/problem_loops.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;

TEST(ProblemLoops, FigureEightHasItsOneCrossingProven) {
  const Problem p = load_problem(problem_test::problems_dir() + "/figure_eight.toml");
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty);
  const TPlane tp = find_loops(p, r.built);
  EXPECT_EQ(tp.eps(), 0.01);
  ASSERT_EQ(tp.nb_complete_detections(), 1u);
  EXPECT_EQ(tp.nb_proofs(), 1u);
  const double pi = std::acos(-1.0);
  for (const Loop& l : tp.detections()) {
    if (!l.complete()) continue;
    EXPECT_TRUE(l.t_box()[0].contains(pi / 2) && l.t_box()[1].contains(3 * pi / 2)) << l.t_box();
    ASSERT_TRUE(l.count());
    EXPECT_EQ(*l.count(), 1u);
    // From v alone, positions relative to the start: x(pi/2) - x(0) = (-10, 0).
    EXPECT_TRUE(l.map_box()[0].contains(-10.0) && l.map_box()[1].contains(0.0)) << l.map_box();
  }
}

TEST(ProblemLoops, Errors) {
  const std::string head = "[time]\ndomain = [0, 6]\ndelta = 0.1\n[var.v]\nkind = \"tube_vector\"\ndim = 3\n"
                           "[var.s]\nkind = \"tube\"\n[[constraint]]\nkind = \"expr\"\nexpr = \"s - v[0]\"\n[output]\n";
  EXPECT_NE(problem_test::error_of(head + "loops = { v = \"v\" }\n").find("found 'v' (tube_vector, dim 3), expected a tube_vector of dim 2"),
            std::string::npos);
  EXPECT_NE(problem_test::error_of(head + "loops = { p = \"v\" }\n").find("found no key 'v'"), std::string::npos)
      << problem_test::error_of(head + "loops = { p = \"v\" }\n");
  EXPECT_NE(problem_test::error_of(head + "loops = { v = \"s\", eps = 0 }\n").find("expected a tube_vector of dim 2"),
            std::string::npos);
  const Problem none = problem_test::parse(head);
  const SolveResult r = solve_problem(none);
  EXPECT_THROW((void)find_loops(none, r.built), Error);
}
