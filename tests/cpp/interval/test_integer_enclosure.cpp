// Integers that are not doubles are enclosed by their two neighbours, as
// Python ints and decimal literals are (issue 12, item 4).
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "sillage/interval/interval.h"

using namespace sillage;

TEST(IntegerEnclosure, ExactAndNeighbours) {
  constexpr double p53 = 0x1p53;
  EXPECT_EQ(Interval(3), Interval(3.0));
  EXPECT_EQ(Interval(std::int64_t{1} << 53), Interval(p53));
  EXPECT_EQ(Interval((std::int64_t{1} << 53) + 1), Interval(p53, p53 + 2));
  EXPECT_EQ(Interval(-(std::int64_t{1} << 53) - 1), Interval(-p53 - 2, -p53));
  EXPECT_EQ(Interval((std::uint64_t{1} << 53) + 3), Interval(p53 + 2, p53 + 4));
  // The largest values round to 2^63 / 2^64, just above them.
  const Interval m = Interval(std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(m, Interval(rounding::next_down(0x1p63), 0x1p63));
  EXPECT_EQ(Interval(std::numeric_limits<std::uint64_t>::max()), Interval(rounding::next_down(0x1p64), 0x1p64));
  EXPECT_EQ(Interval(std::numeric_limits<std::int64_t>::min()), Interval(-0x1p63));
  EXPECT_EQ(Interval(std::size_t{7}) + 1, Interval(8.0));
}
