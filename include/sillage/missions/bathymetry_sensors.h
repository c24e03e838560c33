#pragma once
// The sensors of the synthetic bathymetric mission (thesis 7.3.1) and their
// stated bounds, written as a datasheet would, with margins over what the
// simulation draws:
//  - DVL body velocity (1200 kHz Workhorse class): +-(0.2 % of the speed + 1 mm/s)
//    per axis; the simulation draws a scale bias <= 0.12 %, an offset <= 0.3 mm/s,
//    a white noise <= 0.3 mm/s and quantizes to 0.1 mm/s;
//  - INS heading, pitch, roll (Phins class): +-0.05 deg; drawn: bias <= 0.02 deg,
//    noise <= 0.015 deg, 1e-5 rad quantization;
//  - pressure depth: +-0.05 m; drawn: bias <= 0.01 m, noise <= 0.02 m, 1 cm steps;
//  - DVL altitude: +-(1 % + 0.05 m) around the footprint-filtered seabed;
//    drawn: scale <= 0.4 %, noise <= 0.02 m, 1 cm steps;
//  - the tide model (7.29): +-0.10 m; the simulated sea departs from it by <= 0.04 m;
//  - the vehicle's dynamics class, for the values between samples: angular
//    accelerations <= 1 deg/s^2, body velocity second derivative <= 0.01 m/s^3,
//    horizontal speed <= 1.3 m/s.
//
// The DVL altitude is the seabed seen through the beam footprint (Fig. 7.11):
// four Janus beams at 30 deg from the vertical (azimuths yaw + 45 + k 90 deg),
// each lobe sampled at 5 points (30 +- 2 deg off-nadir, +-4 deg in azimuth);
// the altitude is the mean vertical range. The footprint grows with the
// altitude, and so does the filtering. Its error against the nadir seabed is
// bounded from the seabed class (footprint_filter_bound).
#include <string>
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/missions/bathymetry_dem.h"
#include "sillage/missions/bathymetry_seabed.h"

namespace sillage {

// The stated sensor bounds (datasheet class, with margins) and dynamics class.
struct BathymetrySensorBounds {
  double dvl_scale = 0.002;       // relative, of the measured speed
  double dvl_offset = 0.001;      // m/s
  double heading = 0.05;          // deg
  double attitude = 0.05;         // deg (pitch, roll)
  double depth = 0.05;            // m
  double altitude_scale = 0.01;   // relative, of the measured altitude
  double altitude_offset = 0.05;  // m
  double tide = 0.10;             // m, model error
  double angle_accel = 1.0;       // deg/s^2
  double velocity_accel2 = 0.01;  // m/s^3 (second derivative of the body velocity)
  double speed_max = 1.3;         // m/s, horizontal
  double beam_angle = 30;         // deg off-nadir
  double beam_spread = 2;         // deg, lobe half-width off-nadir
  double beam_azimuth_spread = 4; // deg, lobe half-width in azimuth
};

std::string repr(const BathymetrySensorBounds& b);

// The 20 seabed points of the footprint around (x, y) for a nadir altitude a.
std::vector<Vector> dvl_footprint(double x, double y, double yaw, double altitude,
                                  const BathymetrySensorBounds& b = {});
// The footprint-filtered seabed depth: mean of the DEM over dvl_footprint
// (midpoints of the DEM's point enclosures; truth generation).
double footprint_depth(const BathymetryDem& dem, double x, double y, double yaw, double altitude,
                       const BathymetrySensorBounds& b = {});
// Bound on |footprint_depth - dem(x, y)| for a nadir altitude <= altitude_max:
// the footprint is symmetric about the nadir, so the linear part cancels and
//   kappa rho^2 / 2 + 2 (h^2 kappa / 4) + 2 roughness,
// rho = altitude_max tan(beam_angle + beam_spread) (Taylor with Lagrange
// remainder on the smooth seabed, bilinear interpolation error, roughness).
double footprint_filter_bound(const SeabedClass& seabed, double cell, double altitude_max,
                              const BathymetrySensorBounds& b = {});
// An upper bound of the nadir altitude from a measured altitude: the nadir
// altitude a obeys a <= a_meas + e(a_meas) + c a^2 + c0 (c a^2 + c0 the
// filter bound), so a is below the smaller root of c a^2 - a + K while the
// altitude stays below 1 / (2c) (stated: the water is shallower than that).
// Error if no such root (the measured altitude is too high for the class).
double nadir_altitude_max(double measured, const SeabedClass& seabed, double cell,
                          const BathymetrySensorBounds& b = {});

}  // namespace sillage
