// [[constraint]] kind = "p_implies_z": the temporal SLAM's contractor
// (CtcPImpliesZ) in a problem file, on the example of docs/slam.md: a path
// known from its velocity w within ± 0.2 that crosses itself once, and an
// observation z of the place. The file's network contracts the position
// beyond dead reckoning and keeps the truth; its errors are at their place.
#include <gtest/gtest.h>

#include <cmath>

#include "problem_text.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/problem/solve_problem.h"
#include "sillage/slam/ctc_p_implies_z.h"

using namespace sillage;
using problem_test::expect_error;
using problem_test::parse;

namespace {

const std::string kHead =
    "[time]\ndomain = [0, 5]\ndelta = 0.01\n"
    "[var.p]\nkind = \"tube_vector\"\ndim = 2\nat = [{ t = 0, value = [\"[-4.85, -4.75]\", \"[-4.26, -4.16]\"] }]\n"
    "[var.w]\nkind = \"tube_vector\"\ndim = 2\n"
    "value = [\"10*cos(t - 0.5) + [-0.2, 0.2]\", \"10*cos(2*t - 1) + [-0.2, 0.2]\"]\n"
    "[var.z]\nkind = \"tube\"\n"
    "value = \"sin(10*sin(t - 0.5)/3) + cos(5*sin(2*t - 1)/4) + sin(t - 0.5) + [-0.01, 0.01]\"\n"
    "[[constraint]]\nkind = \"deriv\"\nx = \"p\"\nv = \"w\"\n";  // 18 lines

const std::string kSlam = "[[constraint]]\nkind = \"p_implies_z\"\np = \"p\"\nw = \"w\"\nz = \"z\"\neps = 0.01\n";

}  // namespace

TEST(LoadPImpliesZ, ContractsBeyondDeadReckoningAndKeepsTheTruth) {
  const Problem p = parse(kHead + kSlam);
  const ConstraintSpec& c = p.constraints[1];
  EXPECT_EQ(c.kind, ConstraintKind::PImpliesZ);
  EXPECT_EQ(c.p, "p");
  EXPECT_EQ(c.w, "w");
  EXPECT_EQ(c.z, "z");
  EXPECT_EQ(c.eps, 0.01);
  EXPECT_FALSE(c.fast);
  const SolveResult dr = solve_problem(parse(kHead)), slam = solve_problem(p);
  ASSERT_FALSE(dr.empty || slam.empty) << slam.why_empty;
  const TubeVector &a = *dr.built.var("p").tubes, &b = *slam.built.var("p").tubes;
  const std::size_t n = b.nb_slices();
  // The truth: p(t) = (10 sin(t - 0.5), 5 sin(2t - 1)).
  for (std::size_t k = 0; k <= n; ++k) {
    const double t = b.tdomain()->t(k);
    ASSERT_TRUE(b[0].gate(k).contains(10 * std::sin(t - 0.5))) << t;
    ASSERT_TRUE(b[1].gate(k).contains(5 * std::sin(2 * t - 1))) << t;
    ASSERT_TRUE(b[0].gate(k).is_subset(a[0].gate(k)) && b[1].gate(k).is_subset(a[1].gate(k)));
  }
  // The loop's information narrows the final position (docs/slam.md: more than 10 %).
  EXPECT_LT(b[0].gate(n).diam(), 0.9 * a[0].gate(n).diam());
  // Alg. 14 (fast) as a key, and the check summary names the contractor.
  const Problem fast = parse(kHead + kSlam + "fast = true\n");
  EXPECT_TRUE(fast.constraints[1].fast);
  EXPECT_FALSE(solve_problem(fast).empty);
}

// The file's network is the hand-written one (docs/slam.md: cn.add(CtcDeriv(),
// [p, w]), cn.add(CtcPImpliesZ(eps), [p, w, z])) on the same initial domains:
// the same tubes, bit for bit.
TEST(LoadPImpliesZ, SameTubesAsTheHandWrittenNetwork) {
  const Problem file = parse(kHead + kSlam);
  const BuiltProblem start = build_network(file, 0.01);
  auto p = std::make_shared<TubeVector>(*start.var("p").tubes);
  auto w = std::make_shared<TubeVector>(*start.var("w").tubes);
  auto z = std::make_shared<TubeVector>(*start.var("z").tubes);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {p, w});
  cn.add(std::make_shared<CtcPImpliesZ>(0.01), {p, w, z});
  ASSERT_FALSE(cn.contract().empty);
  const SolveResult r = solve_problem(file);
  ASSERT_FALSE(r.empty);
  const TubeVector& q = *r.built.var("p").tubes;
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t k = 0; k <= q.nb_slices(); ++k) {
      ASSERT_EQ(q[i].gate(k), (*p)[i].gate(k)) << i << " gate " << k;
      if (k < q.nb_slices()) {
        ASSERT_EQ(q[i].slice(k), (*p)[i].slice(k)) << i << " slice " << k;
      }
    }
}

TEST(LoadPImpliesZ, ErrorsAtTheirPlace) {
  expect_error(kHead + "[[constraint]]\nkind = \"p_implies_z\"\np = \"p\"\nw = \"z\"\nz = \"z\"\neps = 0.01\n",
               "test.toml:22:5: found 'z' (tube, dim 1), expected the derivative of 'p'");
  expect_error(kHead + "[[constraint]]\nkind = \"p_implies_z\"\np = \"p\"\nw = \"w\"\nz = \"z\"\neps = 0\n",
               "test.toml:24:7: found eps = 0, expected a width of the t-boxes in (0, tf - t0]");
  expect_error(kHead + "[[constraint]]\nkind = \"p_implies_z\"\np = \"p\"\nw = \"w\"\nz = \"q\"\neps = 0.01\n",
               "test.toml:23:5: found 'q', expected a tube or tube_vector variable");
  expect_error(kHead + kSlam + "fast = 1\n", "test.toml:25:8: found an integer 1, expected true (Alg. 14) or false");
  expect_error(kHead + "[[constraint]]\nkind = \"p_implies_z\"\np = \"p\"\nw = \"w\"\nz = \"z\"\n",
               "test.toml:19:1: found no key 'eps' in constraint 2 (p_implies_z)");
  expect_error(kHead + kSlam + "ratio = 0.1\n", "test.toml:25:1: found the unknown key 'ratio' in constraint 2");
}
