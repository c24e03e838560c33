// examples/problems/loops_survey.toml against examples/cpp/loops_survey.cpp:
// the velocity table generated from the same survey (loops_survey_velocity.h,
// into a temporary folder), solved by the file, gives the same t-plane as the
// example's velocity tube: the same detections (complete and partial), the
// same proofs (Newton and degree) and counts, each detection's t-box equal
// to the example's up to a few ulps. Not bit for bit: a CSV cell is enclosed
// to an ulp around the double written, and the file's gates are the hull of
// their two slices where the example's are the measurements ± e (inside
// that hull); the t-plane integrates the slices.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "../../../examples/problems/loops_survey_velocity.h"
#include "problem_text.h"
#include "sillage/problem/problem_loops.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;

namespace {

bool close(const IntervalVector& a, const IntervalVector& b, double tol) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i].lb() - b[i].lb()) > tol || std::abs(a[i].ub() - b[i].ub()) > tol) return false;
  return true;
}

bool holds(const Loop& l, const PathCrossing& c) {
  for (const IntervalVector& b : l.boxes())
    if (b[0].contains(c.t1) && b[1].contains(c.t2)) return true;
  return false;
}

// The example's velocity tube with its gates replaced by the hull of their two
// slices, as the file's slices from a table give them.
TubeVector hull_gates(const TubeVector& v) {
  std::vector<Tube> comps;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::size_t n = v.nb_slices();
    std::vector<Interval> slices(n), gates(n + 1);
    for (std::size_t k = 0; k < n; ++k) slices[k] = v[i].slice(k);
    for (std::size_t k = 0; k <= n; ++k) gates[k] = slices[k > 0 ? k - 1 : 0] | slices[k < n ? k : n - 1];
    comps.emplace_back(v[i].tdomain(), slices, gates);
  }
  return TubeVector(std::move(comps));
}

TPlane tplane_of(const looping_mission::Mission& m, const TubeVector& v) {
  TPlane tp(m.tdomain());
  tp.compute_detections(m.tf() / 2000, v);  // eps as in the example
  tp.compute_proofs(v);
  return tp;
}

// The same detections, proofs and counts; t-boxes within tol.
void expect_same(const TPlane& file, const TPlane& cpp, bool same_newton) {
  ASSERT_GT(cpp.nb_complete_detections(), 10u);
  ASSERT_EQ(file.nb_detections(), cpp.nb_detections());
  EXPECT_EQ(file.eps(), cpp.eps());
  EXPECT_EQ(file.nb_complete_detections(), cpp.nb_complete_detections());
  EXPECT_EQ(file.nb_proofs(), cpp.nb_proofs());
  std::size_t newton_differ = 0;
  for (std::size_t i = 0; i < cpp.nb_detections(); ++i) {
    const Loop &a = file.detections()[i], &b = cpp.detections()[i];
    EXPECT_EQ(a.complete(), b.complete()) << i;
    EXPECT_EQ(a.proven(), b.proven()) << i;
    EXPECT_EQ(a.count(), b.count()) << i;
    newton_differ += a.proven_newton() != b.proven_newton() ? 1 : 0;
    EXPECT_TRUE(close(a.t_box(), b.t_box(), 1e-9)) << i << ": " << a.t_box() << " vs " << b.t_box();
  }
  EXPECT_LE(newton_differ, same_newton ? 0u : 1u);
}

}  // namespace

TEST(ProblemLoopsSurvey, SameDetectionsAndProofsAsTheExample) {
  const looping_mission::Mission mission{looping_mission::Parameters{}};
  const auto dir = std::filesystem::temp_directory_path() / ("sillage_loops_survey_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  ASSERT_TRUE(loops_survey::write_velocity_csv(mission, dir.string()));
  ::setenv("SILLAGE_SURVEY_DATA", dir.c_str(), 1);
  const Problem p = load_problem(problem_test::problems_dir() + "/loops_survey.toml");
  ::unsetenv("SILLAGE_SURVEY_DATA");
  std::filesystem::remove_all(dir);
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  ASSERT_EQ(r.built.var("v").tubes->nb_slices(), mission.velocity_tube().nb_slices());
  const TPlane file = find_loops(p, r.built);

  // Against the example's tube with the file's gates (the hull of the slices): identical.
  expect_same(file, tplane_of(mission, hull_gates(mission.velocity_tube())), true);
  // Against the example itself (gates: the measurements ± e): the same but for
  // one detection that Newton's ε-inflation proves on the file's wider gates only.
  const TPlane cpp = tplane_of(mission, mission.velocity_tube());
  expect_same(file, cpp, false);
  std::printf("loops survey: %zu detections (%zu complete), lambda_T %zu, lambda_N file %zu, example %zu\n",
              file.nb_detections(), file.nb_complete_detections(), file.nb_proofs(), file.nb_newton_proofs(),
              cpp.nb_newton_proofs());

  // Every true crossing lies in a detection of the file.
  for (const PathCrossing& c : mission.true_crossings(0.05)) {
    bool in = false;
    for (const Loop& l : file.detections()) in = in || holds(l, c);
    EXPECT_TRUE(in) << "crossing at t = " << c.t1 << ", " << c.t2;
  }
}
