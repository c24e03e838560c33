// The tie-line layout of the mission (BathymetryMissionOptions.tie_line_angle):
// a zigzag of legs at a small angle to the north-south rails first, then the
// rails eastward back over them. The path stays in the area, the first leg
// runs at the stated angle to north, the later rails cross the tie lines at
// about that angle, bad angles are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sillage/error.h"
#include "sillage/missions/bathymetry_mission.h"

using namespace sillage;

namespace {

constexpr double kPi = 3.14159265358979323846;

BathymetryMission tie_line_mission(double angle) {
  BathymetryMissionOptions o;
  o.tie_line_angle = angle;
  return BathymetryMission(7, o);
}

// Direction of the path at sample i (rad, from east), by a centred difference over 1 s.
double direction(const BathymetryMission& m, std::size_t i) {
  return std::atan2(m.x2()[i + 5] - m.x2()[i - 5], m.x1()[i + 5] - m.x1()[i - 5]);
}

// The acute angle between two directions (rad, in [0, pi/2]).
double line_angle(double a, double b) {
  double d = std::fmod(std::abs(a - b), kPi);
  return std::min(d, kPi - d);
}

}  // namespace

TEST(TieLineMission, FirstLegAtTheAngleAndInsideTheArea) {
  const BathymetryMission m = tie_line_mission(17);
  for (std::size_t i = 0; i < m.nb_samples(); ++i) {
    ASSERT_GT(m.x1()[i], 10) << i;
    ASSERT_LT(m.x1()[i], 490) << i;
    ASSERT_GT(m.x2()[i], 10) << i;
    ASSERT_LT(m.x2()[i], 490) << i;
  }
  // From the south-east of the rail area, north-west at 17 deg to north.
  EXPECT_GT(m.x1()[0], 400);
  EXPECT_NEAR(m.x2()[0], 100, 1);
  const double dx = m.x1()[2500] - m.x1()[300], dy = m.x2()[2500] - m.x2()[300];
  EXPECT_NEAR(std::atan2(-dx, dy) * 180 / kPi, 17, 1.5);
}

TEST(TieLineMission, LaterRailsCrossTheTieLinesAtTheSmallAngle) {
  const BathymetryMission m = tie_line_mission(17);
  const std::size_t n = m.nb_samples();
  // Early: the tie lines (the first 850 s); late: the rails, from 1200 s.
  std::size_t crossings = 0;
  double last = -1e9;
  for (std::size_t j = 12000; j + 5 < n; j += 5) {
    if (m.times()[j] < last + 60) continue;  // one crossing per pass
    for (std::size_t i = 5; i < 8500; i += 2) {
      // Between the ends of the rails and tie lines (y in [100, 400] m), where both are straight.
      if (m.x2()[j] < 110 || m.x2()[j] > 390) break;
      if (std::hypot(m.x1()[j] - m.x1()[i], m.x2()[j] - m.x2()[i]) < 1.0) {
        const double a = line_angle(direction(m, i), direction(m, j)) * 180 / kPi;
        EXPECT_NEAR(a, 17, 3) << "rail at t = " << m.times()[j] << " s crosses the tie line at t = " << m.times()[i];
        ++crossings;
        last = m.times()[j];
        break;
      }
    }
  }
  // Seed 7: the rails at 217, 257, 377 and 417 m east, and 377 m again on the
  // way back west; those under the turn joining two legs (297, 337 m) cross
  // the turn near its end instead.
  EXPECT_GE(crossings, 5u);
}

TEST(TieLineMission, BadAnglesAreRefused) {
  for (double a : {-1.0, 50.0, std::nan("")}) {
    BathymetryMissionOptions o;
    o.tie_line_angle = a;
    EXPECT_THROW(BathymetryMission(7, o), Error) << a;
  }
  // 0: the default layout, the same mission as without the option.
  BathymetryMissionOptions o;
  o.duration = 300;
  const BathymetryMission a(7, o);
  o.tie_line_angle = 0;
  const BathymetryMission b(7, o);
  EXPECT_EQ(a.x1(), b.x1());
}
