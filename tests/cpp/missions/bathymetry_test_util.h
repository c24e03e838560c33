#pragma once
// Measures of a generated seabed shared by the bathymetry tests.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "sillage/missions/bathymetry_dem.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_sensors.h"

namespace sillage::test {

// Worst second difference of the nodes along x and y (every third row), in metres:
// at most curvature h^2 + 4 roughness for the stated class.
inline double worst_second_difference(const BathymetryDem& d) {
  double worst = 0;
  for (std::size_t j = 1; j + 1 < d.ny(); j += 3)
    for (std::size_t i = 1; i + 1 < d.nx(); ++i) {
      const double dxx = d.node(i + 1, j) - 2 * d.node(i, j) + d.node(i - 1, j);
      const double dyy = d.node(i, j + 1) - 2 * d.node(i, j) + d.node(i, j - 1);
      worst = std::max({worst, std::abs(dxx), std::abs(dyy)});
    }
  return worst;
}

// Worst first difference of the nodes along x (every third row) and y (every
// third column), in metres: at most slope h + 2 roughness for the stated class.
inline double worst_first_difference(const BathymetryDem& d) {
  double worst = 0;
  for (std::size_t j = 0; j < d.ny(); j += 3)
    for (std::size_t i = 0; i + 1 < d.nx(); ++i) worst = std::max(worst, std::abs(d.node(i + 1, j) - d.node(i, j)));
  for (std::size_t i = 0; i < d.nx(); i += 3)
    for (std::size_t j = 0; j + 1 < d.ny(); ++j) worst = std::max(worst, std::abs(d.node(i, j + 1) - d.node(i, j)));
  return worst;
}

// Largest depth range over the 30 m squares of the column x0 .. x0 + 30.
inline double local_spread(const BathymetryDem& d, double x0) {
  double worst = 0;
  for (double y = 20; y < 470; y += 30)
    worst = std::max(worst, d.eval(IntervalVector{Interval(x0, x0 + 30), Interval(y, y + 30)}).diam());
  return worst;
}

// Along the whole mission: |footprint depth - nadir depth| against
// footprint_filter_bound and the true altitude against nadir_altitude_max (a
// failure is reported with its time); returns the worst ratio to the bound.
inline double footprint_bound_worst_ratio(const BathymetryMission& m) {
  const auto& b = m.bounds();
  const double cell = m.dem().cell_size();
  double worst_ratio = 0;
  for (std::size_t i = 0; i < m.nb_samples(); ++i) {
    const double nadir = m.dem()(m.x1()[i], m.x2()[i]).mid();
    const double fp = footprint_depth(m.dem(), m.x1()[i], m.x2()[i], m.truth().yaw[i], m.truth().altitude[i], b);
    const double bound = footprint_filter_bound(m.seabed().bounds, cell, m.truth().altitude[i], b);
    const double alt_max = nadir_altitude_max(m.measured().altitude[i], m.seabed().bounds, cell, b);
    if (std::abs(fp - nadir) > bound || m.truth().altitude[i] > alt_max) {
      ADD_FAILURE() << "footprint or altitude bound violated at t = " << m.times()[i];
      return INFINITY;
    }
    worst_ratio = std::max(worst_ratio, std::abs(fp - nadir) / bound);
  }
  return worst_ratio;
}

}  // namespace sillage::test
