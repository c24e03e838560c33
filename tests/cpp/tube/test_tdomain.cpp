// TDomain: uniform and listed time points, slice lookup at boundaries,
// rigorous widths, sampling that splits every attached tube.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sillage/error.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube.h"

using namespace sillage;

TEST(TDomain, UniformPointsAreComputedDirectly) {
  TDomain td(0.0, 1.0, 0.1);
  ASSERT_EQ(td.nb_slices(), 10u);
  for (std::size_t k = 0; k < 10; ++k) EXPECT_EQ(td.t(k), static_cast<double>(k) * 0.1);  // not accumulated
  EXPECT_EQ(td.t(3), 0.30000000000000004);  // 3 * 0.1
  // 7 * 0.1 = 0.7000000000000001, whereas adding 0.1 seven times gives 0.7
  EXPECT_EQ(td.t(7), 0.7000000000000001);
  EXPECT_EQ(td.t(10), 1.0);
  EXPECT_EQ(td.t0_tf(), Interval(0.0, 1.0));
}

TEST(TDomain, UniformLastSliceMayBeShorterAndEndsAtTf) {
  TDomain td(0.0, 1.05, 0.1);
  ASSERT_EQ(td.nb_slices(), 11u);
  EXPECT_EQ(td.t(10), 1.0);
  EXPECT_EQ(td.t(11), 1.05);
  TDomain td2(0.0, 0.3, 0.1);  // 0.3 / 0.1 rounds below 3: still 3 slices
  ASSERT_EQ(td2.nb_slices(), 3u);
  EXPECT_EQ(td2.t(2), 0.2);
  EXPECT_EQ(td2.t(3), 0.3);
  TDomain td3(1.0, 2.0, 5.0);  // dt larger than the domain: one slice
  ASSERT_EQ(td3.nb_slices(), 1u);
  EXPECT_EQ(td3.slice_domain(0), Interval(1.0, 2.0));
}

TEST(TDomain, UniformRoundingSliverIsMerged) {
  // 1 + 36*0.01 rounds just below 1.36: no sliver slice of width 2e-16 at the end
  ASSERT_LT(1.0 + 36 * 0.01, 1.36);
  TDomain td(1.0, 1.36, 0.01);
  ASSERT_EQ(td.nb_slices(), 36u);
  EXPECT_EQ(td.t(35), 1.0 + 35 * 0.01);
  EXPECT_EQ(td.t(36), 1.36);
}

TEST(TDomain, UniformPointsStrictlyIncreasingOnLongDomains) {
  TDomain td(-3.0, 97.3, 0.01);
  for (std::size_t k = 1; k <= td.nb_slices(); ++k) ASSERT_LT(td.t(k - 1), td.t(k));
  EXPECT_EQ(td.tf(), 97.3);
  EXPECT_LE(td.tf() - td.t(td.nb_slices() - 1), 0.01 * (1 + 1e-12));
}

TEST(TDomain, InvalidConstructionThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(TDomain(0.0, 1.0, 0.0), Error);
  EXPECT_THROW(TDomain(0.0, 1.0, -0.1), Error);
  EXPECT_THROW(TDomain(0.0, 1.0, nan), Error);
  EXPECT_THROW(TDomain(0.0, 1.0, inf), Error);
  EXPECT_THROW(TDomain(1.0, 1.0, 0.1), Error);
  EXPECT_THROW(TDomain(2.0, 1.0, 0.1), Error);
  EXPECT_THROW(TDomain(nan, 1.0, 0.1), Error);
  EXPECT_THROW(TDomain(0.0, inf, 0.1), Error);
  EXPECT_THROW(TDomain(0.0, 1.0, 1e-300), Error);  // too many slices
  EXPECT_THROW(TDomain(std::vector<double>{0.0}), Error);
  EXPECT_THROW(TDomain(std::vector<double>{0.0, 1.0, 1.0}), Error);
  EXPECT_THROW(TDomain(std::vector<double>{0.0, 2.0, 1.0}), Error);
  EXPECT_THROW(TDomain(std::vector<double>{0.0, nan}), Error);
  try {
    TDomain(std::vector<double>{0.0, 2.0, 1.0});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("t[1]"), std::string::npos) << e.what();
  }
}

TEST(TDomain, SliceIndexBoundaryConvention) {
  TDomain td(std::vector<double>{0.0, 1.0, 2.0, 3.0});
  EXPECT_EQ(td.slice_index(0.0), 0u);
  EXPECT_EQ(td.slice_index(0.5), 0u);
  EXPECT_EQ(td.slice_index(1.0), 1u);  // an inner time point belongs to the slice it starts
  EXPECT_EQ(td.slice_index(std::nextafter(1.0, 0.0)), 0u);
  EXPECT_EQ(td.slice_index(2.999), 2u);
  EXPECT_EQ(td.slice_index(3.0), 2u);  // t_N: the last slice
  EXPECT_THROW(td.slice_index(-0.001), Error);
  EXPECT_THROW(td.slice_index(3.001), Error);
  EXPECT_THROW(td.slice_index(std::numeric_limits<double>::quiet_NaN()), Error);
  EXPECT_EQ(td.time_index(2.0), 2);
  EXPECT_EQ(td.time_index(2.5), -1);
  EXPECT_TRUE(td.is_time_point(3.0));
  EXPECT_THROW(td.t(4), OutOfRangeError);
  EXPECT_THROW(td.slice_domain(3), OutOfRangeError);
  EXPECT_EQ(td.slice_domain(1), Interval(1.0, 2.0));
}

TEST(TDomain, SliceWidthIsRigorous) {
  TDomain td(std::vector<double>{1e-20, 1.0, 1.5});
  const Interval w = td.slice_width(0);
  // the real 1 - 1e-20 is not a double: the enclosure is one ulp wide around it
  EXPECT_EQ(w.ub(), 1.0);
  EXPECT_EQ(w.lb(), std::nextafter(1.0, 0.0));
  EXPECT_EQ(td.slice_width(1), Interval(0.5));  // exact
  TDomain td2(std::vector<double>{0.1, 0.3});  // 0.3 - 0.1 happens to be exact in doubles
  const long double exact = static_cast<long double>(0.3) - static_cast<long double>(0.1);
  EXPECT_LE(static_cast<long double>(td2.slice_width(0).lb()), exact);
  EXPECT_GE(static_cast<long double>(td2.slice_width(0).ub()), exact);
}

TEST(TDomain, SampleSplitsEveryAttachedTube) {
  auto td = TDomain::create(std::vector<double>{0.0, 1.0, 2.0});
  Tube x(td, std::vector<Interval>{Interval(0, 1), Interval(2, 3)});
  Tube y(td, Interval(-1, 1));
  EXPECT_EQ(td->nb_attached(), 2u);
  const auto v = x.version();
  EXPECT_EQ(td->sample(1.5), 2u);
  EXPECT_GT(x.version(), v);
  ASSERT_EQ(td->nb_slices(), 3u);
  ASSERT_EQ(x.nb_slices(), 3u);
  ASSERT_EQ(y.nb_slices(), 3u);
  EXPECT_EQ(td->t(2), 1.5);
  EXPECT_EQ(x.slice(1), Interval(2, 3));
  EXPECT_EQ(x.slice(2), Interval(2, 3));
  EXPECT_EQ(x.gate(2), Interval(2, 3));  // the new gate is the slice codomain
  EXPECT_EQ(x.gate(1), Interval::empty());  // [0,1] & [2,3]: untouched
  EXPECT_EQ(x.gate(3), Interval(2, 3));
  EXPECT_EQ(y.slice(2), Interval(-1, 1));
  // already a time point: no-op
  EXPECT_EQ(td->sample(1.0), 1u);
  EXPECT_EQ(td->nb_slices(), 3u);
  EXPECT_EQ(x.nb_slices(), 3u);
  EXPECT_THROW(td->sample(2.5), Error);
  EXPECT_THROW(td->sample(std::numeric_limits<double>::quiet_NaN()), Error);
}

TEST(TDomain, DestroyedTubesDetach) {
  auto td = TDomain::create(0.0, 1.0, 0.25);
  Tube x(td, Interval(0, 1));
  {
    Tube y(td, Interval(0, 2));
    Tube z = y;  // a copy attaches its own storage
    EXPECT_EQ(td->nb_attached(), 3u);
    Tube w = std::move(z);  // a move does not
    EXPECT_EQ(td->nb_attached(), 3u);
  }
  EXPECT_EQ(td->nb_attached(), 1u);
  td->sample(0.1);
  EXPECT_EQ(x.nb_slices(), 5u);
  for (int i = 0; i < 100; ++i) Tube tmp(td);  // entries of dead tubes are purged
  EXPECT_EQ(td->nb_attached(), 1u);
}
