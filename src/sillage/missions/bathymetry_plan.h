#pragma once
// The planned path of the synthetic bathymetric mission as a yaw-rate
// programme: straight legs and turns whose rate is ramped in and out by a
// smoothstep (so the yaw is C^2 with a bounded second derivative), and a depth
// programme of smootherstep changes. Layout on a square area of side L:
// start near the south-west corner, diagonal to the north-east, west along
// the northern edge (or: two east-west transects across the rails), diagonal
// to the south-east (the overall crossing), then north-south rails towards
// the west, joined by keyhole turns (a turn away by beta then back by
// pi + beta, beta chosen for the rail spacing). Or (tie lines): first a
// zigzag of legs at a small angle to the rails across the rail area, east to
// west, then the rails eastward, each crossing a leg at that small angle.
#include <vector>

namespace sillage::detail {

class BathymetryPlan {
 public:
  // transects: the overall crossing as two east-west transects across the
  // rails (at 0.3 and 0.7 size) instead of the first diagonal and the northern edge.
  // tie_angle > 0 (rad, <= pi/4): tie lines at that angle to the rails first,
  // then the rails eastward back over them (transects ignored).
  BathymetryPlan(double size, double speed, double radius, double spacing, double depth, double duration,
                 bool transects = false, double tie_angle = 0);
  double start_x() const { return x0_; }
  double start_y() const { return y0_; }
  double yaw(double t) const;         // rad, counter-clockwise from east
  double yaw_rate(double t) const;    // rad/s
  double depth_rate(double t) const;  // m/s
  static constexpr double kRamp = 6;  // s, turn rate ramps

 private:
  struct Turn {
    double ts, hold, rate;  // start, hold duration, signed rate
  };
  struct DepthChange {
    double ts, dur, delta;
  };
  std::vector<Turn> turns_;
  std::vector<DepthChange> depth_changes_;
  double x0_, y0_, yaw0_;
};

}  // namespace sillage::detail
