// CtcIvp stops soon after its token is cancelled (alone, with pieces, inside
// a network that holds the token), leaves an enclosure, and computes the same
// bits with a token that is never cancelled.
#include <gtest/gtest.h>

#include <chrono>

#include "kit/cancel_after.h"
#include "kit/same_tube.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/interval/elementary.h"

using namespace sillage;
using namespace std::chrono_literals;

namespace {

// x' = -sin x from x(0) = 1 over 10^5 slices: seconds of integration.
Tube long_tube() {
  Tube x(TDomain::create(0.0, 1000.0, 0.01));
  x.set_gate(0, Interval(1.0));
  return x;
}

const CtcIvp& ctc() {
  static const CtcIvp c(Function({"x"}, "-sin(x)"));
  return c;
}

// x(t) = 2 atan(e^{-t} tan(1/2)), in (0, 1]: the gates keep it.
void expect_enclosure(const Tube& x) {
  for (std::size_t k = 0; k <= x.nb_slices(); k += 997) {
    const Interval t(x.tdomain()->t(k));
    ASSERT_TRUE(x.gate(k).intersects(Interval(2.0) * atan(exp(-t) * tan(Interval(0.5))))) << "gate " << k;
  }
}

}  // namespace

TEST(CtcIvpCancel, StopsSoonAfterTheTokenLeavingAnEnclosure) {
  TubeVector x(std::vector<Tube>{long_tube()});  // contracted in place as far as it got
  const CancelToken token;
  EXPECT_LT(test::seconds_to_stop(token, 100ms, [&] { ctc().contract(x, token); }), 2.0);
  EXPECT_LT(x[0].gate(100).diam(), 1e-10);  // the first second was integrated
  expect_enclosure(x[0]);
}

TEST(CtcIvpCancel, StopsWithPiecesToo) {
  TubeVector x(std::vector<Tube>{long_tube()});
  x[0].set_gate(0, Interval(0.9, 1.1));
  CtcIvp pieces(Function({"x"}, "-sin(x)"));
  pieces.set_max_pieces(8);
  const CancelToken token;
  EXPECT_LT(test::seconds_to_stop(token, 100ms, [&] { pieces.contract(x, token); }), 2.0);
}

TEST(CtcIvpCancel, ANetworkPassesItsToken) {
  auto x = std::make_shared<Tube>(long_tube());
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcIvp>(ctc()), {x});
  Budget b;
  cn.set_budget(b);
  EXPECT_LT(test::seconds_to_stop(b.cancel, 100ms, [&] { cn.contract(); }), 2.0);
  expect_enclosure(*x);
}

TEST(CtcIvpCancel, AlreadyCancelledStopsAtOnceAndNeverCancelledChangesNothing) {
  const CancelToken token;
  token.cancel();
  Tube x = long_tube();
  EXPECT_THROW(ctc().contract(x, token), Cancelled);
  Tube a(TDomain::create(0.0, 10.0, 0.1)), b(a.tdomain());
  a.set_gate(0, Interval(1.0));
  b.set_gate(0, Interval(1.0));
  ctc().contract(a);
  ctc().contract(b, CancelToken());
  test::expect_same_bits(a, b);
}
