// CtcPImpliesZ stops soon after its token is cancelled, alone or inside a
// network that holds the token, and p is left as the last complete
// iteration made it.
#include <gtest/gtest.h>

#include <chrono>

#include "kit/cancel_after.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/slam/ctc_p_implies_z.h"
#include "small_slam.h"

using namespace sillage;
using namespace std::chrono_literals;
using sillage::slam_test::SmallSlam;

namespace {

// A t-plane of 10^4 x 10^4 t-boxes per side: about ten seconds of work.
constexpr double kDt = 0.001, kEps = 0.0005;

}  // namespace

TEST(CtcPImpliesZCancel, StopsSoonAfterTheToken) {
  SmallSlam s(kDt);
  const TubeVector before = s.p;
  const CancelToken token;
  EXPECT_LT(test::seconds_to_stop(token, 100ms, [&] { CtcPImpliesZ(kEps).contract(s.p, s.w, s.z, token); }), 2.0);
  EXPECT_TRUE(slam_test::subset_values(s.p, before));
  EXPECT_TRUE(s.p.contains(s.truth));
}

TEST(CtcPImpliesZCancel, ANetworkPassesItsToken) {
  SmallSlam s(kDt);
  auto p = std::make_shared<TubeVector>(s.p);
  auto w = std::make_shared<TubeVector>(s.w);
  auto z = std::make_shared<TubeVector>(s.z);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcPImpliesZ>(kEps), {p, w, z});
  Budget b;
  cn.set_budget(b);
  EXPECT_LT(test::seconds_to_stop(b.cancel, 100ms, [&] { cn.contract(); }), 2.0);
  EXPECT_TRUE(p->contains(s.truth));
}

TEST(CtcPImpliesZCancel, AlreadyCancelledStopsAtOnce) {
  SmallSlam s(0.01);
  const CancelToken token;
  token.cancel();
  EXPECT_THROW(CtcPImpliesZ(0.01).contract(s.p, s.w, s.z, token), Cancelled);
  SlamRow row;
  EXPECT_THROW(CtcPImpliesZ(0.01).iterate(s.p, s.w, s.z, row, token), Cancelled);
}
