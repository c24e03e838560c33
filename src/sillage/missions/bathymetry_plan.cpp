#include "sillage/missions/bathymetry_plan.h"

#include <cmath>

#include "sillage/error.h"

namespace sillage::detail {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Ideal geometry of the plan (constant speed, exact arcs), to lay out the legs.
struct Walker {
  double x, y, h, t, u, R;
  std::vector<double> ts, holds, rates;
  void straight(double len) {
    x += len * std::cos(h), y += len * std::sin(h), t += len / u;
  }
  // A turn of signed angle d: ramp (quasi straight for kRamp/2 on each side), arc.
  void turn(double d, bool record = true) {
    const double ramp = BathymetryPlan::kRamp, r = (d > 0 ? 1 : -1) * u / R, hold = std::abs(d) / std::abs(r) - ramp;
    if (record) ts.push_back(t), holds.push_back(hold), rates.push_back(r);
    const double s = d > 0 ? 1 : -1;
    x += u * ramp / 2 * std::cos(h), y += u * ramp / 2 * std::sin(h);
    x += s * R * (std::sin(h + d) - std::sin(h)), y += s * R * (-std::cos(h + d) + std::cos(h));
    h += d;
    x += u * ramp / 2 * std::cos(h), y += u * ramp / 2 * std::sin(h);
    t += hold + 2 * ramp;
  }
  void straight_to_x(double target) { straight((target - x) / std::cos(h)); }
  void straight_to_y(double target) { straight((target - y) / std::sin(h)); }
};

// Keyhole turn: away by beta, then back by pi + beta (sign s: +1 = ends turned
// counter-clockwise). Lateral shift of the rail, found by bisection.
double keyhole_beta(double u, double R, double spacing) {
  auto shift = [&](double beta) {
    Walker w{0, 0, kPi / 2, 0, u, R, {}, {}, {}};
    w.turn(-beta, false), w.turn(kPi + beta, false);
    return -w.x;  // westward
  };
  double lo = 0, hi = kPi / 2;
  if (shift(lo) < spacing) throw Error("BathymetryPlan: rail spacing larger than a plain U-turn; lower it");
  for (int k = 0; k < 60; ++k) {
    const double mid = (lo + hi) / 2;
    (shift(mid) > spacing ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

double smoothstep(double s) { return s * s * (3 - 2 * s); }
double smoothstep_integral(double s) { return s * s * s - s * s * s * s / 2; }
}  // namespace

namespace {

// The overall crossing (two diagonals joined along the northern edge, or two
// east-west transects), then the rails towards the west; w at the start.
Walker crossing_then_rails(Walker w, double L, double beta, double duration, bool transects) {
  const double m = 0.08 * L, y_lo = 0.2 * L, y_hi = 0.8 * L, R = w.R;
  w.straight_to_x(L - m - 2 * R);
  if (transects) {  // north along the east side, the second transect west, north, then the diagonal
    w.turn(kPi / 2);
    w.straight_to_y(0.7 * L - R);  // the turn adds R: the transect at 0.7 L
    w.turn(kPi / 2);
    w.straight_to_x(m + 2.2 * R);
    w.turn(-kPi / 2);
    w.straight_to_y(L - m - 2 * R);
    w.turn(-3 * kPi / 4);
  } else {  // west along the northern edge, then the diagonal
    w.turn(3 * kPi / 4);
    w.straight_to_x(m + 1.2 * R);
    w.turn(3 * kPi / 4);
  }
  w.straight_to_y(transects ? 0.34 * L : 0.22 * L);  // the rails start ~0.15 L from the east edge
  w.turn(3 * kPi / 4);
  // Boustrophedon towards the west.
  bool north = true;
  while (w.t < duration + 100 && w.x > m + R) {
    w.straight_to_y(north ? y_hi : y_lo);
    if (north) w.turn(-beta), w.turn(kPi + beta);
    else w.turn(beta), w.turn(-kPi - beta);
    north = !north;
  }
  return w;
}

// Tie lines first (the least drift): from the south-east of the rail area,
// legs at alpha to the north-south rails, alternately north-west and
// south-west, joined by turns of pi - 2 alpha that bulge westward, until the
// west side; then the rails towards the east, back over the tie lines, each
// crossing one of them at the small angle alpha (and back west over the same
// rails if the east side comes before the duration); w at the start.
Walker tie_lines_then_rails(Walker w, double L, double beta, double duration, double alpha) {
  const double m = 0.08 * L, y_lo = 0.2 * L, y_hi = 0.8 * L, R = w.R, shift = (y_hi - y_lo) * std::tan(alpha);
  bool north = true;
  while (w.x - 2 * shift - 2 * R > m + R) {
    w.straight_to_y(north ? y_hi : y_lo);
    w.turn(north ? kPi - 2 * alpha : -(kPi - 2 * alpha));
    north = !north;
  }
  w.straight_to_y(north ? y_hi : y_lo);
  w.turn(north ? kPi - alpha : -(kPi - alpha));  // onto the first rail
  north = !north;
  bool east = true;
  while (w.t < duration + 100) {
    w.straight_to_y(north ? y_hi : y_lo);
    if (east && w.x > L - m - 2 * R) east = false;
    if (north == east) w.turn(beta), w.turn(-kPi - beta);
    else w.turn(-beta), w.turn(kPi + beta);
    north = !north;
  }
  return w;
}

}  // namespace

BathymetryPlan::BathymetryPlan(double L, double u, double R, double spacing, double depth, double duration,
                               bool transects, double tie_angle) {
  if (L < 300) throw Error("BathymetryPlan: the area must be at least 300 m wide");
  if (!(tie_angle >= 0 && tie_angle <= kPi / 4)) {
    throw Error("BathymetryPlan: the tie lines' angle to the rails must be in [0, 45] degrees");
  }
  const double beta = keyhole_beta(u, R, spacing);
  const double m = 0.08 * L;
  // The start: the south-east of the rail area (tie lines), the west (transects), the south-west corner.
  x0_ = tie_angle > 0 ? L - m - R : m;
  y0_ = tie_angle > 0 ? 0.2 * L : transects ? 0.3 * L : m;
  yaw0_ = tie_angle > 0 ? kPi / 2 + tie_angle : transects ? 0 : kPi / 4;
  const Walker start{x0_, y0_, yaw0_, 0, u, R, {}, {}, {}};
  const Walker w = tie_angle > 0 ? tie_lines_then_rails(start, L, beta, duration, tie_angle)
                                 : crossing_then_rails(start, L, beta, duration, transects);
  for (std::size_t k = 0; k < w.ts.size(); ++k) turns_.push_back({w.ts[k], w.holds[k], w.rates[k]});
  // Small planned depth changes (+1.5 m, -2 m, +1 m), 90 s each.
  depth_changes_ = {{0.26 * duration, 90, 1.5}, {0.55 * duration, 90, -2.0}, {0.8 * duration, 90, 1.0}};
  (void)depth;
}

double BathymetryPlan::yaw_rate(double t) const {
  double r = 0;
  for (const auto& k : turns_) {
    const double a = t - k.ts;
    if (a <= 0) break;
    if (a < kRamp) r += k.rate * smoothstep(a / kRamp);
    else if (a < kRamp + k.hold) r += k.rate;
    else if (a < 2 * kRamp + k.hold) r += k.rate * (1 - smoothstep((a - kRamp - k.hold) / kRamp));
  }
  return r;
}

double BathymetryPlan::yaw(double t) const {
  double y = yaw0_;
  for (const auto& k : turns_) {
    const double a = t - k.ts;
    if (a <= 0) break;
    if (a < kRamp) y += k.rate * kRamp * smoothstep_integral(a / kRamp);
    else if (a < kRamp + k.hold) y += k.rate * (kRamp / 2 + (a - kRamp));
    else if (a < 2 * kRamp + k.hold) {
      const double s = (a - kRamp - k.hold) / kRamp;
      y += k.rate * (kRamp / 2 + k.hold + kRamp * (s - smoothstep_integral(s)));
    } else y += k.rate * (kRamp + k.hold);
  }
  return y;
}

double BathymetryPlan::depth_rate(double t) const {
  double r = 0;
  for (const auto& c : depth_changes_) {
    const double s = (t - c.ts) / c.dur;
    if (s > 0 && s < 1) r += c.delta / c.dur * 30 * s * s * (1 - s) * (1 - s);  // smootherstep'
  }
  return r;
}

}  // namespace sillage::detail
