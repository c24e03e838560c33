// A TDomain that grows (extend) and forgets its past (forget_before), with
// every tube on it following: online estimation's time domain.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sillage/error.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;

TEST(TDomainGrow, ExtendAppendsAnUnknownSliceToEveryTube) {
  auto td = TDomain::create({0.0, 1.0});
  Tube x(td, Interval(1, 2));
  TubeVector v(td, 2, Interval(-1, 1));
  const auto version = x.version();
  EXPECT_EQ(td->extend(2.5), 2u);
  EXPECT_EQ(td->tf(), 2.5);
  ASSERT_EQ(x.nb_slices(), 2u);
  EXPECT_EQ(x.slice(0), Interval(1, 2));
  EXPECT_EQ(x.gate(1), Interval(1, 2));  // the old last gate keeps its value
  EXPECT_TRUE(x.slice(1).is_all_reals());  // nothing known of the future
  EXPECT_TRUE(x.gate(2).is_all_reals());
  EXPECT_EQ(v[1].nb_slices(), 2u);
  EXPECT_GT(x.version(), version);
  EXPECT_EQ(x(Interval(0, 1)), Interval(1, 2));
}

TEST(TDomainGrow, ExtendRefusesATimeThatIsNotAfterTheEnd) {
  auto td = TDomain::create({0.0, 1.0});
  EXPECT_THROW(td->extend(1.0), Error);
  EXPECT_THROW(td->extend(0.5), Error);
  EXPECT_THROW(td->extend(std::nan("")), Error);
  EXPECT_THROW(td->extend(std::numeric_limits<double>::infinity()), Error);
  EXPECT_EQ(td->nb_slices(), 1u);
}

TEST(TDomainGrow, ForgetDropsWholeSlicesAndKeepsTheNewFirstGate) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  Tube x(td);
  for (std::size_t k = 0; k < 10; ++k) x.set(Interval(k, k + 0.5), k);
  x.set_gate(4, Interval(3.9, 4.1));
  EXPECT_EQ(td->forget_before(4.5), 4u);  // slices [0,1] .. [3,4] end at or before 4.5
  EXPECT_EQ(td->nb_forgotten(), 4u);
  EXPECT_EQ(td->t0(), 4.0);
  ASSERT_EQ(x.nb_slices(), 6u);
  EXPECT_EQ(x.gate(0), Interval(3.9, 4.1));
  EXPECT_EQ(x.slice(0), Interval(4, 4.5));
  EXPECT_EQ(x(9.5), Interval(9, 9.5));
  EXPECT_EQ(td->forget_before(4.0), 0u);  // slice [4, 5] does not end by 4
  EXPECT_EQ(td->forget_before(-3.0), 0u);
  EXPECT_EQ(td->forget_before(100.0), 5u);  // the last slice always stays
  EXPECT_EQ(x.nb_slices(), 1u);
  EXPECT_EQ(td->nb_forgotten(), 9u);
  EXPECT_THROW(td->forget_before(std::nan("")), Error);
}

// Growing and forgetting for a long time keeps memory to the window.
TEST(TDomainGrow, MemoryFollowsTheWindowNotTheMission) {
  auto td = TDomain::create({0.0, 0.1});
  Tube x(td, Interval(0, 1));
  std::size_t most = 0;
  for (int k = 2; k <= 100000; ++k) {
    const double t = 0.1 * k;
    td->extend(t);
    x.write().slices().back() = Interval(0, 1);
    if (t - 60 - td->t0() >= 7.5) td->forget_before(t - 60);
    most = std::max(most, x.nb_slices());
  }
  EXPECT_LE(most, 676u);  // (60 + 7.5) / 0.1 + 1
  EXPECT_GE(x.nb_slices(), 600u);
  EXPECT_EQ(td->nb_forgotten() + td->nb_slices(), 100000u);
  EXPECT_LT(std::abs(td->tf() - 10000.0), 1e-6);
}
