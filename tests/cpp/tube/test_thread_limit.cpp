// ThreadLimit: the smallest limit alive holds, and what sillage computes on
// several threads (tubes from expressions, copies and whole-line tubes of
// 65536 elements and more, sin, cos, exp... of tubes) is the same under a
// limit of one thread.
#include <gtest/gtest.h>

#include "sillage/error.h"
#include "sillage/interval/elementary.h"
#include "sillage/threads.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_arithmetic.h"

#include "kit/same_tube.h"

using namespace sillage;

namespace {

using test::expect_same_bits;

// The tubes f computes, with all threads and with one.
template <class F>
void expect_same_under_one_thread(F f) {
  const auto all = f();
  const ThreadLimit one(1);
  const auto alone = f();
  ASSERT_EQ(all.size(), alone.size());
  for (std::size_t i = 0; i < all.size(); ++i) expect_same_bits(all[i], alone[i]);
}

}  // namespace

TEST(ThreadLimit, TheSmallestLimitAliveHolds) {
  const std::size_t all = ThreadLimit::current();
  ASSERT_GE(all, 1u);
  {
    const ThreadLimit one(1);
    EXPECT_EQ(one.threads(), 1u);
    EXPECT_EQ(ThreadLimit::current(), 1u);
    const ThreadLimit three(3);
    EXPECT_EQ(ThreadLimit::current(), 1u);
  }
  EXPECT_EQ(ThreadLimit::current(), all);
  EXPECT_THROW(ThreadLimit(0), Error);
}

TEST(ThreadLimit, TubesAreTheSameUnderAnyLimit) {
  const auto td = TDomain::create(0.0, 100.0, 0.001);  // 10^5 slices: every parallel path
  const Tube x(td, "exp(-t/20)*sin(3*t) + [-0.01, 0.01]");
  expect_same_under_one_thread([&] {
    const Tube copy(x);
    Tube assigned(TDomain::create(0.0, 1.0, 0.5), Interval(0.0));
    assigned = x;
    return std::vector<Tube>{Tube(td, "exp(-t/20)*sin(3*t) + [-0.01, 0.01]"), copy, assigned,
                             Tube(td, Interval(-1.0, 2.0)), exp(x), atan(x), sqrt(x), sin(x), cos(x), x + Interval(1.0, 2.0)};
  });
  expect_same_bits(Tube(x), x);
}
