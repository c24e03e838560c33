// ThreadLimit: the smallest limit alive holds, and a tube built under a
// limit of one thread is the tube built with all of them.
#include <gtest/gtest.h>

#include "sillage/error.h"
#include "sillage/threads.h"
#include "sillage/tube/tube.h"

#include "kit/same_bits.h"

using namespace sillage;

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

TEST(ThreadLimit, ATubeIsTheSameUnderAnyLimit) {
  const auto td = TDomain::create(0.0, 50.0, 0.001);
  const Tube all(td, "exp(-t/20)*sin(3*t) + [-0.01, 0.01]");
  const ThreadLimit one(1);
  const Tube alone(td, "exp(-t/20)*sin(3*t) + [-0.01, 0.01]");
  for (std::size_t k = 0; k < all.nb_slices(); ++k) ASSERT_TRUE(test::same_bits(all.slice(k), alone.slice(k))) << k;
  for (std::size_t k = 0; k <= all.nb_slices(); ++k) ASSERT_TRUE(test::same_bits(all.gate(k), alone.gate(k))) << k;
}
