// The sin/cos (sinh/cosh) pairs of TaylorOde (src/sillage/expr/taylor.h):
// one pair recurrence gives both series, so sin x and cos x of the same
// operand (f = −sin x and its Jacobian −cos x) share it. Checked: which
// nodes are twins, the shared series bit for bit against the unshared run,
// and a system using both against closed forms.
#include <gtest/gtest.h>

#include <vector>

#include "sillage/expr/taylor.h"

using namespace sillage;

namespace {

std::vector<Interval> run(const Function& f, const std::vector<Interval>& x0, int order, bool variational) {
  detail::TaylorOde ode(f);
  std::vector<Interval> x = x0, v;
  const bool ok = variational ? ode.coefficients(x, v, nullptr, order, 1.0) : ode.coefficients(x, nullptr, order, 1.0);
  EXPECT_TRUE(ok);
  return x;
}

std::size_t nb_twins(const std::vector<std::uint32_t>& twin) {
  std::size_t n = 0;
  for (std::uint32_t t : twin) n += t != detail::kNoTwin;
  return n;
}

}  // namespace

TEST(TaylorPairs, TwinsAreTheOtherHalfOfAPairOnTheSameOperand) {
  const std::vector<std::string> xy{"x", "y"};
  // cos x after sin x: one twin; cos y has no sin y; sinh x and cosh x: one.
  const Function f(xy, "(sin(x) + cos(x) + cos(y), sinh(x)*cosh(x))");
  const detail::Tape tape(f.exprs(), f.var_names());
  const std::vector<std::uint32_t> twin = detail::pair_twins(tape);
  EXPECT_EQ(nb_twins(twin), 2u);
  for (std::size_t s = 0; s < twin.size(); ++s) {
    if (twin[s] == detail::kNoTwin) continue;
    const detail::Instr &in = tape.code()[s], &tw = tape.code()[twin[s]];
    EXPECT_LT(twin[s], s);
    EXPECT_EQ(in.a, tw.a);
    EXPECT_TRUE((in.op == Op::Cos && tw.op == Op::Sin) || (in.op == Op::Sin && tw.op == Op::Cos) ||
                (in.op == Op::Cosh && tw.op == Op::Sinh) || (in.op == Op::Sinh && tw.op == Op::Cosh));
  }
  // A pair is shared once: a third node on x of the same kind has no twin.
  const Function g({"x"}, "sin(x)*cos(x)");
  EXPECT_EQ(nb_twins(detail::pair_twins(detail::Tape(g.exprs(), g.var_names()))), 1u);
  const Function h({"x"}, "sin(x)*sin(2*x)");
  EXPECT_EQ(nb_twins(detail::pair_twins(detail::Tape(h.exprs(), h.var_names()))), 0u);
}

TEST(TaylorPairs, SharedSeriesAreBitForBitTheUnsharedOnes) {
  // With the variational equation the tape holds f and its Jacobian: −sin x
  // and −cos x share one pair; without it, −sin x runs alone. The state
  // coefficients must be the same intervals exactly, from a point and a box.
  const std::vector<Function> fs{Function({"x"}, "-sin(x)"), Function({"x"}, "cos(x)"),
                                 Function({"x"}, "sinh(x) - x"), Function({"x"}, "exp(-x)*cos(x)")};
  for (const Function& f : fs) {
    for (const Interval& x0 : {Interval(1.0), Interval(0.9, 1.1)}) {
      const std::vector<Interval> a = run(f, {x0}, 20, false), b = run(f, {x0}, 20, true);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].lb(), b[k].lb()) << f << " order " << k;
        EXPECT_EQ(a[k].ub(), b[k].ub()) << f << " order " << k;
      }
    }
  }
}

TEST(TaylorPairs, BothHalvesMatchClosedForms) {
  // x' = cos x, y' = sin x from (0, 0): x = gd(t) = 2 atan(tanh(t/2)),
  // y = log cosh t. gd(t) = t − t³/6 + t⁵/24 − 61t⁷/5040,
  // log cosh t = t²/2 − t⁴/12 + t⁶/45 − 17t⁸/2520.
  const std::vector<Interval> c = run(Function({"x", "y"}, "(cos(x), sin(x))"), {Interval(0.0), Interval(0.0)}, 8,
                                      false);
  const auto q = [](double p, double r) { return Interval(p) / Interval(r); };
  const std::vector<Interval> gd{q(0, 1), q(1, 1), q(0, 1), q(-1, 6), q(0, 1), q(1, 24), q(0, 1), q(-61, 5040), q(0, 1)};
  const std::vector<Interval> lc{q(0, 1), q(0, 1), q(1, 2), q(0, 1), q(-1, 12), q(0, 1), q(1, 45), q(0, 1), q(-17, 2520)};
  for (std::size_t k = 0; k <= 8; ++k) {
    EXPECT_TRUE(c[2 * k].intersects(gd[k])) << "x order " << k << ": " << c[2 * k] << " vs " << gd[k];
    EXPECT_TRUE(c[2 * k + 1].intersects(lc[k])) << "y order " << k << ": " << c[2 * k + 1] << " vs " << lc[k];
    EXPECT_LT(c[2 * k].diam(), 1e-14);
    EXPECT_LT(c[2 * k + 1].diam(), 1e-14);
  }
}
