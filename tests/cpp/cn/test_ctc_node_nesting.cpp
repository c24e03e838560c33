// A box contractor that runs a network of its own inside contract() (a Python
// contractor may): CtcNode reuses its boxes per thread and nesting level, so
// the inner network must not disturb the outer node's box.
#include <gtest/gtest.h>

#include <memory>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"

using namespace sillage;

namespace {

// On (x, y): x + y = 3 (nested: through an inner network on three variables,
// so that the inner box has another size; else directly), then y - x = 1.
class Nested : public Ctc {
 public:
  explicit Nested(bool nested) : Ctc(2), nested_(nested) {}
  void contract(IntervalVector& box) const override {
    const CtcFunction sum(Function({"x", "y", "s"}, "x + y - s"));
    if (nested_) {
      ContractorNetwork inner;
      auto x = inner.create_dom(box[0]), y = inner.create_dom(box[1]), s = inner.create_dom(Interval(3.0));
      inner.add(std::make_shared<CtcFunction>(sum), {x, y, s});
      inner.contract();
      box[0] &= *x;
      box[1] &= *y;
    } else {
      IntervalVector b{box[0], box[1], Interval(3.0)};  // what the inner network does: one run
      sum.contract(b);
      box[0] &= b[0];
      box[1] &= b[1];
    }
    CtcFunction(Function({"x", "y"}, "y - x - 1")).contract(box);
  }
  std::string name() const override { return "Nested"; }

 private:
  bool nested_;
};

// The outer network: Nested on (x, y), and x = 2 z; returns x, y, z at its fixed point.
IntervalVector solve(bool nested) {
  ContractorNetwork cn;
  cn.set_ratio(0);
  auto x = cn.create_dom(Interval(-10, 10), "x"), y = cn.create_dom(Interval(-10, 10), "y");
  auto z = cn.create_dom(Interval(0, 10), "z");
  cn.add(std::make_shared<Nested>(nested), {x, y});
  cn.add(std::make_shared<CtcFunction>(Function({"x", "z"}, "x - 2*z")), {x, z});
  EXPECT_FALSE(cn.contract().empty);
  return IntervalVector{*x, *y, *z};
}

}  // namespace

TEST(CtcNodeNesting, InnerNetworkLeavesTheOuterBoxAlone) {
  // x + y = 3, y = x + 1, x = 2 z: the truth (1, 2, 0.5) kept, and the same boxes as without nesting.
  const IntervalVector a = solve(true), b = solve(false);
  EXPECT_TRUE(a[0].contains(1.0) && a[1].contains(2.0) && a[2].contains(0.5));
  EXPECT_EQ(a, b);
  EXPECT_LT(a[0].diam(), 20.0);  // contracted
}
