// ContractorNetwork::set_scheduling (cn/scheduling.h): FIFO keeps the order
// in which contractors were woken; Priority runs first, within a round, the
// contractor that shrank the largest share of its atoms last time per atom to
// look at; both reach the same fixed point.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"

using namespace sillage;

namespace {

// Records the order of its calls in a shared log.
class Logged : public Ctc {
 public:
  Logged(std::shared_ptr<const Ctc> c, int id, std::shared_ptr<std::vector<int>> log)
      : Ctc(c->nb_vars()), c_(std::move(c)), id_(id), log_(std::move(log)) {}
  void contract(IntervalVector& x) const override {
    log_->push_back(id_);
    c_->contract(x);
  }
  std::string name() const override { return "Logged(" + c_->name() + ")"; }

 private:
  std::shared_ptr<const Ctc> c_;
  int id_;
  std::shared_ptr<std::vector<int>> log_;
};

// A small cyclic network (c^2 - c - 3 = 0 at its solution), run to the true fixed point.
struct Net {
  std::shared_ptr<std::vector<int>> log = std::make_shared<std::vector<int>>();
  ContractorNetwork cn;
  std::shared_ptr<Interval> a, b, c, d;
  explicit Net(Scheduling s) {
    a = cn.create_dom(Interval(0, 10), "a");
    b = cn.create_dom(Interval(-1, 6), "b");
    c = cn.create_dom(Interval(1, 5), "c");
    d = cn.create_dom(Interval(-5, 5), "d");
    cn.set_ratio(0);
    cn.set_scheduling(s);
    // 0: d = b - a (the wide one), 1: a = sqr(c), 2: b = 2*c, 3: c = d + 3.
    cn.add(std::make_shared<Logged>(std::make_shared<CtcFunction>(Function({"d", "b", "a"}, "d - (b - a)")), 0, log), {d, b, a});
    cn.add(std::make_shared<Logged>(std::make_shared<CtcFunction>(Function({"a", "c"}, "a - sqr(c)")), 1, log), {a, c});
    cn.add(std::make_shared<Logged>(std::make_shared<CtcFunction>(Function({"b", "c"}, "b - 2*c")), 2, log), {b, c});
    cn.add(std::make_shared<Logged>(std::make_shared<CtcFunction>(Function({"c", "d"}, "c - (d + 3)")), 3, log), {c, d});
  }
};

}  // namespace

TEST(CnScheduling, DefaultIsFifo) {
  ContractorNetwork cn;
  EXPECT_EQ(cn.scheduling(), Scheduling::Fifo);
  cn.set_scheduling(Scheduling::Priority);
  EXPECT_EQ(cn.scheduling(), Scheduling::Priority);
}

TEST(CnScheduling, SameFixedPointOtherOrder) {
  Net fifo(Scheduling::Fifo), prio(Scheduling::Priority);
  const ContractStats fs = fifo.cn.contract(), ps = prio.cn.contract();
  ASSERT_FALSE(fs.empty || ps.empty);
  EXPECT_EQ(*fifo.a, *prio.a);
  EXPECT_EQ(*fifo.b, *prio.b);
  EXPECT_EQ(*fifo.c, *prio.c);
  EXPECT_EQ(*fifo.d, *prio.d);
  // Round 1 is the order of add() for both (no history yet).
  ASSERT_GE(fifo.log->size(), 4u);
  ASSERT_GE(prio.log->size(), 4u);
  EXPECT_EQ(std::vector<int>(fifo.log->begin(), fifo.log->begin() + 4), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(std::vector<int>(prio.log->begin(), prio.log->begin() + 4), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(fs.contractor_calls, fifo.log->size());
  EXPECT_EQ(ps.contractor_calls, prio.log->size());
}

TEST(CnScheduling, PriorityRunsTheMostContractingFirst) {
  // Two contractors woken by the same domain x: p shrank all of its atoms in
  // round 1 (y from the whole line), q none (z in x + [-100, 100] leaves z in [-50, 50] as
  // it is); when w then shrinks x, round 2 runs p before q under Priority,
  // in the order they were woken (q first: added first) under FIFO.
  for (const Scheduling s : {Scheduling::Fifo, Scheduling::Priority}) {
    auto log = std::make_shared<std::vector<int>>();
    ContractorNetwork cn;
    cn.set_scheduling(s);
    auto x = cn.create_dom(Interval(0, 10), "x");
    auto y = cn.create_dom(Interval(), "y");
    auto z = cn.create_dom(Interval(-50, 50), "z");
    cn.add(std::make_shared<Logged>(std::make_shared<CtcFunction>(Function({"z", "x"}, "z - x + [-100, 100]")), 1, log), {z, x});
    cn.add(std::make_shared<Logged>(std::make_shared<CtcFunction>(Function({"y", "x"}, "y - x")), 0, log), {y, x});
    cn.add(std::make_shared<Logged>(std::make_shared<CtcFunction>(Function({"x"}, "x - [2, 3]")), 2, log), {x});
    const ContractStats st = cn.contract();
    ASSERT_FALSE(st.empty);
    ASSERT_GE(log->size(), 5u);
    EXPECT_EQ(std::vector<int>(log->begin(), log->begin() + 3), (std::vector<int>{1, 0, 2}));
    const std::vector<int> round2(log->begin() + 3, log->begin() + 5);
    EXPECT_EQ(round2, s == Scheduling::Fifo ? (std::vector<int>{1, 0}) : (std::vector<int>{0, 1}));
    EXPECT_EQ(*y, Interval(2, 3));
  }
}
