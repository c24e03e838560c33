// Loop detection while the robot moves (thesis ch. 6 on the window, docs/online.md):
// the t-plane of the window's velocity tube, computed at any time, proves the
// figure eight's loop once the robot has come back to its crossing, not before.
#include <gtest/gtest.h>

#include <cmath>

#include "sillage/expr/function.h"
#include "sillage/loops/tplane.h"
#include "sillage/online/online_estimator.h"

using namespace sillage;

namespace {

// The proven loops of the window's path, from its velocity tube.
std::vector<Loop> proven_loops(const OnlineEstimator& est) {
  const auto v = est.tube("v");
  TPlane tp(v->tdomain());
  tp.compute_detections(0.01, *v);
  tp.compute_proofs(*v);
  std::vector<Loop> proven;
  for (const Loop& l : tp.detections())
    if (l.complete() && l.proven()) proven.push_back(l);
  return proven;
}

}  // namespace

TEST(OnlineLoops, TheFigureEightLoopIsProvenOnceTheRobotIsBack) {
  // v = (-10 sin t, 10 cos 2t) +- 0.01: the path crosses itself at t = pi/2 and 3 pi/2.
  OnlineEstimator est(0.0);
  est.add_bounded("v", Function({"t"}, "(-10*sin(t) + [-0.01, 0.01], 10*cos(2*t) + [-0.01, 0.01])"));
  est.add_state("x", 2, IntervalVector{{9.9, 10.1}, {-0.1, 0.1}});
  est.add_deriv("x", "v");
  for (int k = 1; k <= 80; ++k) est.advance(0.05 * k);  // t = 4: the crossing not yet passed again
  EXPECT_TRUE(proven_loops(est).empty());
  for (int k = 81; k <= 120; ++k) est.advance(0.05 * k);  // t = 6
  const std::vector<Loop> loops = proven_loops(est);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_TRUE(loops[0].t_box()[0].contains(M_PI / 2)) << loops[0].t_box();
  EXPECT_TRUE(loops[0].t_box()[1].contains(3 * M_PI / 2)) << loops[0].t_box();
  const IntervalVector x = est.now("x");  // the bound of t held along the way: x(6) = (10 cos 6, 5 sin 12)
  EXPECT_TRUE(x[0].contains(10 * std::cos(6.0)) && x[1].contains(5 * std::sin(12.0))) << x;
}
