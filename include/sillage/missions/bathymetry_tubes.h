#pragma once
// The tubes a temporal SLAM needs (thesis 7.3), built from the measurements of
// a BathymetryMission and its stated bounds, on a TDomain whose time points
// are sample times (BathymetryMission::tdomain(dt)). Every tube encloses the
// truth at every time, rounding included:
//  - the sensor tubes, at the sensor period: gate i = measurement +- bound,
//    slice i = hull of both gates + the interpolation margin a h^2 / 8 (a the
//    second-derivative bound of the dynamics class: a C^1 signal with |x''| <= a
//    departs from its chord by at most a h^2 / 8);
//  - w = R(psi, theta, phi) v_r (7.31), (4.32), by tube arithmetic at the
//    sensor period, then the slices of `td` the hulls of the fine slices;
//  - p = x0 + integral of w (the library's primitive) at the sensor period, so
//    the gates on `td` keep the fine integration; its third component is the
//    depth (positive down): the pressure depth +- its bound at every sample,
//    the integrated depth rate in between (primitive_from_increments);
//  - z = z_alt + z_depth + z_tide (7.30), the seabed depth below the chart
//    datum under the vehicle: measured altitude + measured depth - tide model
//    (7.29), each with its bound, plus the footprint filter bound
//    (bathymetry_sensors.h); between samples |z'| <= slope bound x speed_max.
// Error if a time of `td` is not a sample time of the mission.
#include <memory>

#include "sillage/interval/interval_vector.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/trajectory_arithmetic.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// The attitude and DVL tubes (psi, theta, phi, vx, vy, vz) on `td`.
TubeVector bathymetry_sensor_tubes(const BathymetryMission& m, const std::shared_ptr<TDomain>& td);
// w: (east, north, depth) velocity.
TubeVector bathymetry_velocity_tube(const BathymetryMission& m, const std::shared_ptr<TDomain>& td);
// p: (east, north, depth) from p(t0) in x0 (3 components).
TubeVector bathymetry_dead_reckoning(const BathymetryMission& m, const std::shared_ptr<TDomain>& td,
                                     const IntervalVector& x0);
// The start box of a survey: the truth at t0 +- `horizontal` (a GNSS fix at the
// dive) east and north, the measured depth +- its bound.
IntervalVector bathymetry_initial_box(const BathymetryMission& m, double horizontal = 1.0);
// z: the observation tube (7.30).
Tube bathymetry_observation_tube(const BathymetryMission& m, const std::shared_ptr<TDomain>& td);
// Bound on |z'| used between samples (m/s).
double bathymetry_observation_rate_bound(const BathymetryMission& m);
// The truth: (east, north, depth) sampled at the sensor period.
TrajectoryVector bathymetry_truth(const BathymetryMission& m);
// The true observation: the DEM under the true path (midpoints of tight enclosures).
Trajectory bathymetry_truth_observation(const BathymetryMission& m);

}  // namespace sillage
