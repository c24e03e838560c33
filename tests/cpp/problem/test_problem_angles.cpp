// Angle tubes in problem files (angle = true): a robot turning in place for
// five turns, its heading unknown at the start, found from bearings to a
// landmark modulo 2π and checked against its truth modulo 2π; and the uses
// of an angle that would read it as a real value, refused at their place.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "data_tables.h"
#include "problem_text.h"
#include "sillage/interval/angle.h"
#include "sillage/problem/bound_audit.h"
#include "sillage/problem/report_html.h"

using namespace sillage;
using problem_test::data_dir;
using problem_test::expect_error;
using problem_test::table;

namespace {

// ψ(t) = 0.5 t + 1, turning in place at the origin; the landmark at (3, 4);
// a bearing every 2 s, b = atan2(4, 3) - ψ wrapped to (-π, π].
std::string turning_robot(const std::string& heading_extra) {
  std::ofstream bearings(data_dir() + "/bearings.csv");
  bearings << "t,b\n";
  for (int i = 1; i < 30; ++i) {
    const double t = 2.0 * i;
    bearings << t << "," << std::remainder(std::atan2(4.0, 3.0) - (0.5 * t + 1), 2 * M_PI) << "\n";
  }
  std::ofstream truth(data_dir() + "/heading_truth.csv");
  truth << "t,psi\n";
  for (int i = 0; i <= 600; ++i) truth << i / 10.0 << "," << 0.5 * (i / 10.0) + 1 << "\n";
  bearings.close();
  truth.close();
  return table("bearings", "bearings.csv") + table("truth", "heading_truth.csv") +
         "[time]\ndomain = [0, 60]\ndelta = 0.1\n"
         "[var.psi]\nkind = \"tube\"\n" + heading_extra +
         "[var.omega]\nkind = \"tube\"\nvalue = \"[0.45, 0.55]\"\n"
         "[[constraint]]\nkind = \"deriv\"\nx = \"psi\"\nv = \"omega\"\n"
         "[[constraint]]\nkind = \"eval\"\ndata = \"bearings\"\ny = \"psi\"\nv = \"omega\"\ntime = \"t\"\n"
         "time_error = 0.01\nexpr = \"atan2(4, 3) - psi - b + [-0.02, 0.02]\"\n"
         "[output]\ntruth = { data = \"truth\", time = \"t\", columns = { psi = [\"psi\"] } }\n";
}

}  // namespace

TEST(ProblemAngles, AHeadingUnknownAtTheStartIsFoundFromBearingsModuloTwoPi) {
  const std::string text = turning_robot("angle = true\n");
  ASSERT_EQ(problem_test::error_of(text), "");
  const Problem p = problem_test::parse(text);
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  const TruthCheck c = check_truth(p, r.built);
  EXPECT_EQ(c.samples, 601u);
  EXPECT_EQ(c.inside, c.samples) << (c.first_misses.empty() ? "" : c.first_misses[0]);
  // Past the first bearing every gate is narrower than a turn: 0.04 of the
  // bearing, and at most 1 s of ±0.05 rad/s drift to the nearest bearing.
  const Tube& psi = (*r.built.var("psi").tubes)[0];
  for (std::size_t k = 20; k <= 580; ++k) ASSERT_LT(psi.gate(k).diam(), 0.2) << k << " " << psi.gate(k);
  // The bound audit reads the bearing modulo 2π: the truth, 30 rad on, uses
  // a few millionths (the file's 6 digits) of the 0.02 allowed, not turns.
  bool audited = false;
  for (const AuditLine& l : audit_problem(p)) {
    if (l.name.find("(eval)") == std::string::npos) continue;
    audited = true;
    EXPECT_NEAR(l.allowed, 0.02, 1e-12);
    EXPECT_LT(l.used, 1e-4) << l.how;
  }
  EXPECT_TRUE(audited);
}

TEST(ProblemAngles, UsesThatWouldReadAnAngleAsARealAreRefused) {
  const std::string base = turning_robot("angle = true\n");
  const auto with = [&](const std::string& extra) { return base + extra; };
  expect_error(with("[[constraint]]\nkind = \"expr\"\nexpr = \"2*psi - omega\"\n"),
               "outside sin, cos, tan and the top-level sum");
  expect_error(with("[[constraint]]\nkind = \"increment\"\nx = \"psi\"\nv = \"omega\"\n"),
               "the angle 'psi' in");
  expect_error(with("[[constraint]]\nkind = \"expr\"\nexpr = \"psi + psi - omega\"\n"), "as a term and elsewhere too");
  expect_error(with("[[constraint]]\nkind = \"eval\"\ndata = \"bearings\"\ny = \"psi\"\ntime = \"t\"\nexpr = \"psi - b\"\n"),
               "evaluated without its rate");
  expect_error(turning_robot("angle = \"yes\"\n"), "expected true (values known modulo 2 pi) or false");
  expect_error(turning_robot("angle = true\n[var.q]\nkind = \"tube_vector\"\ndim = 2\nangle = true\n"),
               "angle = true on a scalar tube");
  // In a tuple, each equation on its own: an angle term in one, refused outside sin/cos in another.
  const std::string eval = "[[constraint]]\nkind = \"eval\"\ndata = \"bearings\"\ny = \"psi\"\nv = \"omega\"\ntime = \"t\"\n";
  EXPECT_EQ(problem_test::error_of(with(eval + "expr = \"(atan2(4, 3) - psi - b + [-0.1, 0.1], cos(psi) - cos(b) + [-2, 2])\"\n")), "");
  expect_error(with(eval + "expr = \"(atan2(4, 3) - psi - b, 2*psi - b)\"\n"), "outside sin, cos, tan");
  // Under sin and cos, and as a term: accepted.
  EXPECT_EQ(problem_test::error_of(with("[[constraint]]\nkind = \"expr\"\nexpr = \"cos(psi + 0.1)*sin(psi) - omega + 0.5 + [-1, 1]\"\n")), "");
}

// The real log: UTIAS MRCLAM robot 1, its heading an angle tube. Every Vicon
// sample is inside, position and heading (modulo 2π), with the file's bounds.
TEST(ProblemAngles, MrclamRobot1KeepsTheTruthModuloTwoPi) {
  const Problem p = load_problem(problem_test::problems_dir() + "/mrclam_robot1.toml");
  const SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  const Tube& psi = (*r.built.var("psi").tubes)[0];
  EXPECT_TRUE(psi.is_angle());
  const TubeVector& pos = *r.built.var("p").tubes;
  const CsvTable& truth = p.table("truth")->table;
  std::size_t n = 0;
  for (std::size_t row = 0; row < truth.nb_rows(); row += 7) {
    const auto v = truth.row(row);
    const double t = v[truth.column("t_s")];
    if (t < r.built.td->t0() || t > r.built.td->tf()) continue;
    ++n;
    ASSERT_TRUE(pos[0](t).contains(v[truth.column("x_m")]) && pos[1](t).contains(v[truth.column("y_m")])) << t;
    ASSERT_TRUE(angle_contains(psi(t), v[truth.column("heading_rad")])) << t << " " << psi(t);
  }
  EXPECT_GT(n, 8000u);
  // A heading that is the whole circle proves nothing: a miss, said as such.
  const TruthCheck c = check_truth(p, r.built);
  ASSERT_FALSE(c.first_misses.empty());
  EXPECT_NE(c.first_misses[0].find("psi = -2.1781 at t = 18.286 in the whole circle"), std::string::npos) << c.first_misses[0];
}
