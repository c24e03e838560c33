// A derivative tube from an expression undefined at t = 0 (issue 12, item 2):
// Tube::is_empty(), the ContractorNetwork and the direct CtcDeriv call agree.
#include <gtest/gtest.h>

#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"

using namespace sillage;

namespace {

// Direct call and network on copies of (x, v); returns "consistent" and
// checks that both say the same and contract x alike.
bool direct_equals_network(const Tube& x, const Tube& v) {
  Tube direct = x;
  const bool ok = CtcDeriv().contract(direct, v);
  auto nx = std::make_shared<Tube>(x), nv = std::make_shared<Tube>(v);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcDeriv>(), {nx, nv});
  const ContractStats s = cn.contract();
  EXPECT_EQ(ok, !s.empty);
  EXPECT_EQ(ok, !direct.is_empty());
  if (ok) {
    EXPECT_EQ(*nx, direct);
  } else {
    EXPECT_TRUE(nx->is_empty() || nv->is_empty());
  }
  return ok;
}

}  // namespace

TEST(DerivUndefined, NetworkAndDirectCallAgree) {
  auto td = TDomain::create(0.0, 10.0, 0.1);
  for (const char* e : {"sin(t)/t", "log(t)", "1/t", "t*log(t)", "atan2(t, t)"}) {
    SCOPED_TRACE(e);
    const Tube v(td, e);
    ASSERT_FALSE(v.is_empty());
    Tube x(td);
    x.set_gate(50, Interval(1.0));
    EXPECT_TRUE(direct_equals_network(x, v));
  }
}

TEST(DerivUndefined, AnEmptyGateOfVIsNoSolutionEverywhere) {
  auto td = TDomain::create(0.0, 10.0, 0.1);
  Tube v(td, Interval(-1, 1));
  v.set_gate(30, Interval::empty());
  ASSERT_TRUE(v.is_empty());
  EXPECT_FALSE(direct_equals_network(Tube(td), v));
  Tube x(td);
  EXPECT_FALSE(CtcDeriv().contract(x, v, 29, 29));  // the range reads gates 29 and 30
  EXPECT_TRUE(x.is_empty());
  Tube y(td);
  EXPECT_TRUE(CtcDeriv().contract(y, v, 0, 10));  // far from it: nothing read there
}
