#pragma once
// BathymetryMission: a synthetic AUV survey like Daurade's of 20 October 2015
// (thesis 7.3.2, Fig. 7.16), deterministic from a seed: 5760 s at 0.1 s
// steps over a generated seabed (bathymetry_seabed.h), an overall crossing of
// the area (two diagonals joined along the northern edge) then a boustrophedon
// of north-south rails closer than twice the turning radius, so that every turn
// is a keyhole loop and the turns at one end overlap; constant-ish depth with
// two planned depth changes.
//
// Frames: world (x1 east, x2 north, x3 up), body (forward, left, up); yaw psi
// counter-clockwise from east, pitch theta positive nose down, roll phi; the
// world velocity is R(psi, theta, phi) v_r with R the Euler matrix (4.32),
// (7.31). Depths are positive down (depth = -x3).
//
// The truth is a continuous model: smooth yaw, attitude and body velocity
// signals (turn rates ramped in, so their second derivatives stay within the
// stated dynamics class), the position their integral (3-point Gauss-Legendre
// on each 0.1 s step: error far below the millimetre). The measurements are
// drawn inside the stated bounds (bathymetry_sensors.h) from independent
// streams of the seeded generator.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sillage/missions/bathymetry_seabed.h"
#include "sillage/missions/bathymetry_sensors.h"
#include "sillage/slam/bathymetry_tide.h"
#include "sillage/tube/tdomain.h"

namespace sillage {

// Options of BathymetryMission.
struct BathymetryMissionOptions {
  double duration = 5760;    // s (1 h 36)
  double step = 0.1;         // s, sensor period
  double speed = 1.03;       // m/s (2 knots)
  double turn_radius = 28;   // m
  double rail_spacing = 40;  // m (< 2 turn_radius: keyhole turns)
  double depth = 14.5;       // m, depth below the surface at the start
  // The overall crossing as two east-west transects across the north-south
  // rails (at 30 % and 70 % of the side) instead of a diagonal and the
  // northern edge: every rail crosses them at right angles.
  bool transects = false;
  // > 0: the tie-line layout instead: a zigzag of tie lines at this angle
  // (degrees, at most 45) to the north-south rails across the rail area
  // first, then the rails eastward back over them, each crossing a tie line
  // at this small angle (transects is then ignored). 0: no tie lines.
  double tie_line_angle = 0;
  // The SeabedOptions.
  SeabedOptions seabed;
  // The TideModel.
  TideModel tide;
  // The BathymetrySensorBounds.
  BathymetrySensorBounds bounds;
};

// The bank mission: the bank seabed (bank_seabed_options), the east-west
// transects (the southern one flown first up the western flank, the northern
// one along the northern flank; the late rails in the west cross both) and a
// narrow-beam altimeter (6 deg cone: the channel puts the seabed up to ~34 m
// below the vehicle, where the 30 deg Janus footprint would blur it by metres).
BathymetryMissionOptions bank_mission_options();

// Signals at the sample times, one value per sample.
struct BathymetrySignals {
  std::vector<double> yaw, pitch, roll;  // rad
  std::vector<double> vx, vy, vz;        // body velocity, m/s
  std::vector<double> depth;             // m, positive down
  std::vector<double> altitude;          // m (truth: nadir; measured: DVL, footprint-filtered)
};

class BathymetryMission {
 public:
  // Generates the mission (about 0.4 s).
  explicit BathymetryMission(std::uint64_t seed, const BathymetryMissionOptions& options = {});

  // The seed.
  std::uint64_t seed() const { return seed_; }
  // The BathymetryMissionOptions.
  const BathymetryMissionOptions& options() const { return options_; }
  // The Seabed.
  const Seabed& seabed() const { return seabed_; }
  // The BathymetryDem of the seabed.
  const BathymetryDem& dem() const { return seabed_.dem; }
  // The BathymetrySensorBounds.
  const BathymetrySensorBounds& bounds() const { return options_.bounds; }
  // The TideModel.
  const TideModel& tide() const { return options_.tide; }

  // Number of samples.
  std::size_t nb_samples() const { return times_.size(); }
  // Sample times (s).
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& x1() const { return x1_; }  // truth, east
  const std::vector<double>& x2() const { return x2_; }  // truth, north
  // The true BathymetrySignals.
  const BathymetrySignals& truth() const { return truth_; }
  // The measured BathymetrySignals.
  const BathymetrySignals& measured() const { return meas_; }
  const std::vector<double>& tide_truth() const { return tide_truth_; }       // sea height above datum
  const std::vector<double>& filtered_altitude() const { return alt_filt_; }  // DVL altitude before noise

  double path_length() const;  // horizontal, m
  // A TDomain whose time points are every (dt / step)-th sample time (dt a
  // multiple of step, else Error): the domain the tube builders accept.
  std::shared_ptr<TDomain> tdomain(double dt) const;
  // Index of the sample at time t exactly, or -1.
  std::ptrdiff_t sample_index(double t) const;

 private:
  std::uint64_t seed_;
  BathymetryMissionOptions options_;
  Seabed seabed_;
  std::vector<double> times_, x1_, x2_, tide_truth_, alt_filt_;
  BathymetrySignals truth_, meas_;
};

std::string repr(const BathymetryMission& m);

}  // namespace sillage
