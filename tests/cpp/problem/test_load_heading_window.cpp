// The constraint kinds "second_deriv" (CtcSecondDeriv) and "heading_window"
// (CtcHeadingWindow): a file using them builds the network a hand-written
// program adding the same contractors in the same order builds (the same
// sets, bit for bit), and their keys are checked, each error at its
// file:line:column.
#include <gtest/gtest.h>

#include "problem_text.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/dynamics/ctc_second_deriv.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;
using problem_test::expect_error;
using problem_test::parse;

namespace {

// A vehicle driving east at 1 m/s, turning slowly: 20 s in slices of 0.5 s.
const std::string kVars =
    "[time]\ndomain = [0, 20]\ndelta = 0.5\n"
    "[var.p]\nkind = \"tube_vector\"\ndim = 2\nat = [{ t = 0, value = [\"[-0.1, 0.1]\", \"[-0.1, 0.1]\"] }]\n"
    "[var.psi]\nkind = \"tube\"\nat = [{ t = 0, value = \"[-0.05, 0.05]\" }]\n"
    "[var.dpsi]\nkind = \"tube\"\nvalue = \"[-0.01, 0.01]\"\n"
    "[var.d]\nkind = \"tube\"\nvalue = \"[0.49, 0.51]\"\n"
    "[var.w]\nkind = \"tube\"\nvalue = \"[-1, 1]\"\n"
    "[var.a]\nkind = \"tube\"\nvalue = \"[-2, 2]\"\n"
    "[[constraint]]\nkind = \"increment\"\nx = \"psi\"\nv = \"dpsi\"\n"
    "[[constraint]]\nkind = \"deriv\"\nx = \"psi\"\nv = \"w\"\n";  // lines 1-30

const std::string kSecondDeriv = "[[constraint]]\nkind = \"second_deriv\"\nx = \"psi\"\na = \"a\"\n";
const std::string kHeading = "[[constraint]]\nkind = \"heading\"\np = \"p\"\npsi = \"psi\"\ndist = \"d\"\nomega = \"w\"\n"
                             "track = 0.05\n";
const std::string kWindow = "[[constraint]]\nkind = \"heading_window\"\np = \"p\"\npsi = \"psi\"\ndist = \"d\"\n"
                            "dpsi = \"dpsi\"\nomega = \"w\"\ntrack = 0.05\nwindow = 4\nturn_accel = 2\n";

}  // namespace

TEST(LoadHeadingWindow, IsTheHandWrittenNetwork) {
  const Problem prob = parse(kVars + kSecondDeriv + kHeading + kWindow);
  EXPECT_EQ(prob.constraints[2].kind, ConstraintKind::SecondDeriv);
  EXPECT_EQ(prob.constraints[4].kind, ConstraintKind::HeadingWindow);
  EXPECT_STREQ(kind_name(ConstraintKind::HeadingWindow), "heading_window");
  const SolveResult r = solve_problem(prob);
  ASSERT_FALSE(r.empty) << r.why_empty;

  const auto td = TDomain::create(0, 20, 0.5);
  auto p = std::make_shared<TubeVector>(td, 2);
  p->set_gate(0, IntervalVector{{-0.1, 0.1}, {-0.1, 0.1}});
  auto psi = std::make_shared<Tube>(td);
  psi->set_gate(0, Interval(-0.05, 0.05));
  auto dpsi = std::make_shared<Tube>(td, Interval(-0.01, 0.01));
  auto d = std::make_shared<Tube>(td, Function({"t"}, "[0.49, 0.51]"));  // the decimals, enclosed as the file does
  auto w = std::make_shared<Tube>(td, Interval(-1, 1));
  auto a = std::make_shared<Tube>(td, Interval(-2, 2));
  const double track = Function({"t"}, "0.05").eval(IntervalVector{Interval(0)}).ub();
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcIncrement>(), {psi, dpsi});
  cn.add(std::make_shared<CtcDeriv>(), {psi, w});
  cn.add(std::make_shared<CtcSecondDeriv>(), {psi, a});
  cn.add(std::make_shared<CtcHeading>(track), {p, psi, d, w});
  // stride: a quarter of the 4 s window at 0.5 s slices.
  cn.add(std::make_shared<CtcHeadingWindow>(4.0, track, 2.0, 2), {p, psi, d, dpsi, w});
  const ContractStats s = cn.contract();
  ASSERT_FALSE(s.empty);
  EXPECT_EQ(r.schedule.back().stats.contractor_calls, s.contractor_calls);
  const TubeVector& fp = *r.built.var("p").tubes;
  const Tube& fpsi = (*r.built.var("psi").tubes)[0];
  for (std::size_t k = 0; k <= td->nb_slices(); ++k) {
    EXPECT_EQ(fpsi.gate(k), psi->gate(k)) << k;
    for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(fp[i].gate(k), (*p)[i].gate(k)) << k;
  }
  // The windows and the turn acceleration tighten the heading (a property: never wider).
  const SolveResult plain = solve_problem(parse(kVars + kHeading));
  const Tube& ppsi = (*plain.built.var("psi").tubes)[0];
  for (std::size_t k = 0; k < td->nb_slices(); ++k) EXPECT_TRUE(fpsi.slice(k).is_subset(ppsi.slice(k))) << k;
  EXPECT_LT(fpsi.volume(), ppsi.volume());
}

TEST(LoadHeadingWindow, StrideGivenOrAQuarterWindow) {
  EXPECT_EQ(parse(kVars + kWindow).constraints[2].stride, 0u);  // a quarter window, at build time
  const Problem p = parse(kVars + kWindow + "stride = 3\n");
  EXPECT_EQ(p.constraints[2].stride, 3u);
  EXPECT_EQ(p.constraints[2].window, 4.0);
  EXPECT_EQ(p.constraints[2].turn_accel, "2");
  EXPECT_FALSE(solve_problem(p).empty);
}

TEST(LoadHeadingWindow, Errors) {
  // kVars ends on line 30; the constraint's keys follow from line 31.
  expect_error(kVars + "[[constraint]]\nkind = \"second_deriv\"\nx = \"psi\"\nv = \"a\"\n",
               "test.toml:34:1: found the unknown key 'v' in constraint 3 (second_deriv)");
  expect_error(kVars + "[[constraint]]\nkind = \"second_deriv\"\nx = \"psi\"\na = \"p\"\n",
               "test.toml:34:5: found 'p' (tube_vector, dim 2), expected a variable of the kind and dimension of 'psi'");
  expect_error(kVars + "[[constraint]]\nkind = \"second_deriv\"\nx = \"psi\"\na = \"zz\"\n", "test.toml:34:5: found 'zz'");
  expect_error(kVars + kWindow + "windw = 3\n", "found the unknown key 'windw' in constraint 3 (heading_window)");
  expect_error(kVars + kWindow + "stride = 0\n", "test.toml:41:10: found stride = 0, expected an integer >= 1 (slices)");
  expect_error(kVars + kWindow + "stride = 1.5\n", "test.toml:41:10: found a number, expected a window every `stride` slices (an integer >= 1)");
  const std::string no_window = "[[constraint]]\nkind = \"heading_window\"\np = \"p\"\npsi = \"psi\"\ndist = \"d\"\n"
                                "dpsi = \"dpsi\"\nomega = \"w\"\n";
  expect_error(kVars + no_window, "test.toml:31:1: found no key 'window' in constraint 3 (heading_window), expected 'window' = the length of the windows (s, a number > 0)");
  expect_error(kVars + no_window + "window = 0\n", "test.toml:38:10: found window = 0, expected a window length > 0 (s)");
  expect_error(kVars + no_window + "window = \"4\"\n", "test.toml:38:10: found a string \"4\", expected the length of the windows");
  expect_error(kVars + no_window + "window = 4\nturn_accel = -1\n",
               "test.toml:39:14: found turn_accel = -1, expected a turn acceleration bound > 0 (rad/s^2)");
  expect_error(kVars + no_window + "window = 4\ntrack = -0.1\n", "found a negative track error");
  expect_error(kVars + "[[constraint]]\nkind = \"heading_window\"\np = \"p\"\npsi = \"psi\"\ndist = \"d\"\ndpsi = \"p\"\n"
                       "omega = \"w\"\nwindow = 4\n",
               "test.toml:36:8: found the tube_vector 'p', expected a scalar tube");
  expect_error(kVars + "[[constraint]]\nkind = \"heading_windows\"\n", "\"second_deriv\", \"increment\", \"eval\", \"heading\", \"heading_window\", \"p_implies_z\" or \"python\"");
}
