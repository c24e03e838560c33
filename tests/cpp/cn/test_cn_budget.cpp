// The network's budget: contractor calls, cancellation, and the domains left
// as enclosures when it stops; contract_run and ContractStats::summary.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

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


// contract_run: the same propagation, its end told by ContractStats::summary.

TEST(CnOutcome, AFixedPointConverges) {
  Halving h;
  const ContractStats s = h.cn.contract_run();
  EXPECT_EQ(s.summary.status, Status::Converged);
  EXPECT_EQ(s.summary.reason, "");
  EXPECT_EQ(s.summary.rounds, s.iterations);
  EXPECT_EQ(s.summary.work, s.contractor_calls);
  EXPECT_EQ(s.summary.seconds, s.time);
}

TEST(CnOutcome, AnEmptyDomainIsNoSolutionWithItsProvenance) {
  ContractorNetwork cn;
  auto x = cn.create_dom(Interval(0, 1), "x");
  cn.add(std::make_shared<CtcFunction>(Function({"x"}, "x - 5")), {x});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.summary.status, Status::NoSolution);
  EXPECT_EQ(s.summary.reason, s.emptiness);
  EXPECT_FALSE(s.summary.reason.empty());
}

TEST(CnOutcome, ASpentBudgetIsAnAnswerWithTheDomainsSoFar) {
  Halving h;
  Budget b;
  b.max_boxes = 5;
  h.cn.set_budget(b);
  const ContractStats s = h.cn.contract_run();
  EXPECT_EQ(s.summary.status, Status::Stopped);
  EXPECT_EQ(s.summary.reason,
            "ContractorNetwork::contract: budget exceeded: 6 contractor calls > max_boxes = 5; raise the "
            "network's budget (set_budget).max_boxes (0: no limit)");
  EXPECT_EQ(s.contractor_calls, 5u);
  EXPECT_FALSE(s.summary.finished());
  EXPECT_TRUE(h.x->is_subset(Interval(-1, 1)) && h.x->contains(0.0) && h.x->diam() < 2);  // contracted, still an enclosure
  // The throwing form: the same stop, its stats kept.
  Halving g;
  g.cn.set_budget(b);
  EXPECT_THROW(g.cn.contract(), BudgetExceeded);
  EXPECT_EQ(g.cn.stopped_stats().contractor_calls, 5u);
  EXPECT_EQ(g.cn.stopped_stats().summary.status, Status::Stopped);
  EXPECT_EQ(*g.x, *h.x);
}

TEST(CnOutcome, ACancelledTokenIsAnAnswer) {
  Halving h;
  Budget b;
  b.cancel.cancel();
  h.cn.set_budget(b);
  const ContractStats s = h.cn.contract_run();
  EXPECT_EQ(s.summary.status, Status::Cancelled);
  EXPECT_EQ(s.summary.reason, "ContractorNetwork::contract: cancelled");
  EXPECT_EQ(*h.x, Interval(-1, 1));
}

TEST(CnOutcome, TheHookIsCalledOncePerRound) {
  Halving h;
  std::vector<Progress> seen;
  Budget b;
  b.progress = [&](const Progress& p) { seen.push_back(p); };
  h.cn.set_budget(b);
  const ContractStats s = h.cn.contract();
  ASSERT_EQ(seen.size(), s.iterations);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].round, i + 1);
    EXPECT_STREQ(seen[i].where, "ContractorNetwork::contract");
    if (i > 0) {
      EXPECT_GE(seen[i].work, seen[i - 1].work);
    }
  }
  EXPECT_EQ(seen.back().work, s.contractor_calls);
}

}  // namespace
}  // namespace sillage
