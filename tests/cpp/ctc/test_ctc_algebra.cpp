// Contractor algebra (thesis 2.34): hand cases, the order of CtcCompo, the
// fixed point, operators, errors, and random comparisons with set operations.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "ctc/ctc_test_util.h"
#include "sillage/ctc/ctc_algebra.h"
#include "sillage/ctc/ctc_binary.h"
#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/ctc_function.h"

using namespace sillage;
using sillage::test::random_around;

namespace {

std::shared_ptr<CtcBox> box_ctc(const IntervalVector& b) { return std::make_shared<CtcBox>(b); }

// Records its tag when called (test-only: not thread-safe).
class Tagged : public Ctc {
 public:
  Tagged(int tag, std::vector<int>* log) : Ctc(1), tag_(tag), log_(log) {}
  void contract(IntervalVector& x) const override {
    check_dim(x);
    log_->push_back(tag_);
  }

 private:
  int tag_;
  std::vector<int>* log_;
};

}  // namespace

TEST(CtcAlgebra, InterUnionCompoOfBoxes) {
  const auto c1 = box_ctc(IntervalVector{{0, 2}, {0, 2}});
  const auto c2 = box_ctc(IntervalVector{{1, 3}, {1, 3}});
  const IntervalVector x(2, Interval(-10, 10));
  IntervalVector a(x), b(x), c(x);
  CtcInter({c1, c2}).contract(a);
  EXPECT_EQ(a, IntervalVector(2, Interval(1, 2)));
  CtcUnion({c1, c2}).contract(b);
  EXPECT_EQ(b, IntervalVector(2, Interval(0, 3)));
  CtcCompo({c1, c2}).contract(c);
  EXPECT_EQ(c, IntervalVector(2, Interval(1, 2)));
  // Union with a contractor that empties: only the other one counts.
  IntervalVector d(x);
  CtcUnion({box_ctc(IntervalVector(2, Interval(20, 30))), c2}).contract(d);
  EXPECT_EQ(d, IntervalVector(2, Interval(1, 3)));
  IntervalVector e(x);
  CtcInter({box_ctc(IntervalVector(2, Interval(20, 30))), c2}).contract(e);
  EXPECT_TRUE(e.is_empty());
}

TEST(CtcAlgebra, InterIsLooserThanCompo) {
  // z = x + y then y ∈ [1, 1]: the composition propagates y's bound into z,
  // the intersection applies both to the same input box.
  const auto add = std::make_shared<CtcAdd>();
  const auto fix_y = box_ctc(IntervalVector{Interval(), Interval(), {1, 1}});
  const IntervalVector x{Interval(), {0, 1}, {-5, 5}};
  IntervalVector inter(x), compo(x);
  (add & fix_y)->contract(inter);
  CtcCompo({fix_y, add}).contract(compo);  // fix_y first, then add
  EXPECT_EQ(compo, (IntervalVector{{1, 2}, {0, 1}, {1, 1}}));
  EXPECT_EQ(inter, (IntervalVector{{-5, 6}, {0, 1}, {1, 1}}));
}

TEST(CtcAlgebra, CompoAppliesTheListInOrder) {
  std::vector<int> log;
  const auto a = std::make_shared<Tagged>(1, &log), b = std::make_shared<Tagged>(2, &log),
             c = std::make_shared<Tagged>(3, &log);
  IntervalVector x(1);
  CtcCompo({a, b, c}).contract(x);
  EXPECT_EQ(log, (std::vector<int>{1, 2, 3}));
  // An empty box stops the composition.
  log.clear();
  CtcCompo({a, box_ctc(IntervalVector{{5, 6}}), b}).contract(x = IntervalVector{{0, 1}});
  EXPECT_EQ(log, (std::vector<int>{1}));
  EXPECT_TRUE(x.is_empty());
}

TEST(CtcAlgebra, FixPointReachesTheIntersection) {
  // x = y and y = x / 2 + 1: the only solution is (2, 2).
  const auto c1 = std::make_shared<CtcFunction>(Function({"x", "y"}, "x - y"));
  const auto c2 = std::make_shared<CtcFunction>(Function({"x", "y"}, "y - x / 2 - 1"));
  const auto both = std::make_shared<CtcCompo>(std::vector<CtcPtr>{c1, c2});
  IntervalVector one_pass(2, Interval(0, 10)), fixed(2, Interval(0, 10)), exact(2, Interval(0, 10));
  both->contract(one_pass);
  CtcFixPoint(both).contract(fixed);
  CtcFixPoint(both, 0.0).contract(exact);
  EXPECT_GT(one_pass[0].diam(), 1.0);
  for (const auto& b : {fixed, exact}) {
    EXPECT_TRUE(b[0].contains(2) && b[1].contains(2)) << b;
  }
  EXPECT_LT(fixed.max_diam(), 0.1);
  EXPECT_LT(exact.max_diam(), 1e-12);
  EXPECT_TRUE(exact.is_subset(fixed));
}

TEST(CtcAlgebra, OperatorsAndErrors) {
  const auto c1 = box_ctc(IntervalVector(2, Interval(0, 1)));
  const auto c2 = box_ctc(IntervalVector(2, Interval(0.5, 2)));
  const auto i = c1 & c2;
  const auto u = c1 | c2;
  EXPECT_EQ(i->list().size(), 2u);
  IntervalVector a(2), b(2);
  i->contract(a);
  u->contract(b);
  EXPECT_EQ(a, IntervalVector(2, Interval(0.5, 1)));
  EXPECT_EQ(b, IntervalVector(2, Interval(0, 2)));
  // Nested: (c1 | c2) & c1 == c1.
  IntervalVector c(2);
  ((c1 | c2) & c1)->contract(c);
  EXPECT_EQ(c, IntervalVector(2, Interval(0, 1)));

  const auto c3 = box_ctc(IntervalVector(3));
  EXPECT_THROW(CtcInter({c1, c3}), DimensionError);
  EXPECT_THROW((void)(c1 | c3), DimensionError);
  EXPECT_THROW(CtcUnion({}), Error);
  EXPECT_THROW(CtcCompo({c1, nullptr}), Error);
  EXPECT_THROW(CtcFixPoint(nullptr), Error);
  EXPECT_THROW(CtcFixPoint(c1, 1.0), Error);
  EXPECT_THROW(CtcFixPoint(c1, -0.1), Error);
  IntervalVector wrong(3);
  try {
    i->contract(wrong);
    FAIL() << "no DimensionError";
  } catch (const DimensionError& e) {
    EXPECT_NE(std::string(e.what()).find("CtcInter"), std::string::npos) << e.what();
  }
}

TEST(CtcAlgebra, RandomBoxesMatchSetOperations) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int trial = 0; trial < 2000; ++trial) {
    IntervalVector b1(3), b2(3), x(3);
    for (std::size_t i = 0; i < 3; ++i) {
      b1[i] = random_around(u(rng), rng);
      b2[i] = random_around(u(rng), rng);
      x[i] = random_around(u(rng), rng);
    }
    const auto c1 = box_ctc(b1), c2 = box_ctc(b2);
    IntervalVector i(x), un(x), co(x);
    (c1 & c2)->contract(i);
    (c1 | c2)->contract(un);
    CtcCompo({c1, c2}).contract(co);
    ASSERT_EQ(i, x & b1 & b2);
    ASSERT_EQ(co, x & b1 & b2);
    ASSERT_EQ(un, (x & b1) | (x & b2));
    ASSERT_TRUE(i.is_subset(x) && un.is_subset(x));
  }
}
