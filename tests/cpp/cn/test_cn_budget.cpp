// The network's budget: contractor calls, cancellation, and the domains left
// as enclosures when it stops.
#include <gtest/gtest.h>

#include <memory>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"

namespace sillage {
namespace {

// x = y / 2 and y = x / 2 with ratio 0: they wake each other for a long time
// (each round halves the bounds) before the fixed point {0}.
struct Halving {
  ContractorNetwork cn;
  std::shared_ptr<Interval> x = cn.create_dom(Interval(-1, 1)), y = cn.create_dom(Interval(-1, 1));
  Halving() {
    cn.add(std::make_shared<CtcFunction>(Function({"x", "y"}, "x - y/2")), {x, y});
    cn.add(std::make_shared<CtcFunction>(Function({"x", "y"}, "y - x/2")), {x, y});
    cn.set_ratio(0);
  }
};

TEST(CnBudget, ContractorCallsAreCounted) {
  Halving h;
  Budget b;
  b.max_boxes = 5;
  h.cn.set_budget(b);
  try {
    h.cn.contract();
    FAIL() << "no BudgetExceeded";
  } catch (const BudgetExceeded& e) {
    EXPECT_STREQ(e.what(),
                 "ContractorNetwork::contract: budget exceeded: 6 contractor calls > max_boxes = 5; raise the "
                 "network's budget (set_budget).max_boxes (0: no limit)");
  }
  EXPECT_TRUE(h.x->is_subset(Interval(-1, 1)) && h.x->contains(0.0));  // an enclosure still
}

TEST(CnBudget, CancelledTokenStopsIt) {
  Halving h;
  Budget b;
  b.cancel.cancel();
  h.cn.set_budget(b);
  EXPECT_THROW(h.cn.contract(), Cancelled);
  b.cancel.reset();
  const ContractStats s = h.cn.contract();  // the same token, reset: runs to the fixed point
  EXPECT_FALSE(s.empty);
  EXPECT_TRUE(h.x->contains(0.0) && h.x->diam() < 1e-300);
}

TEST(CnBudget, DefaultBudgetIsLargeAndChecked) {
  ContractorNetwork cn;
  EXPECT_EQ(cn.budget().max_boxes, 10'000'000u);
  Budget bad;
  bad.max_seconds = -1;
  EXPECT_THROW(cn.set_budget(bad), Error);
}

}  // namespace
}  // namespace sillage
