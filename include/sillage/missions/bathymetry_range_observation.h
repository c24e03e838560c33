#pragma once
// Observation tubes of a range-only temporal SLAM without the beacon
// positions (issue 13, plaza1): z(.) = the ranges to the beacons, each a tube
// built from its own measurements. A range is a time-invariant function of
// the position (p(t1) = p(t2) => z(t1) = z(t2)) whatever the beacons' places,
// so the SLAM needs no map at all.
//
// Assumptions (stated bounds, RangeBounds): a measurement r_j stamped t_j was
// taken at a true time within t_j +- time_err, and true - measured lies in
// [-long_err, short_err] (RF ranges are biased long); the range changes at
// most as fast as the robot moves, |z'| <= speed. So at any t,
//   z(t) in [r_j - long_err, r_j + short_err] + [-1, 1] speed (|t - t_j| + time_err)
// for every measurement j of the beacon; a slice (gate) of the tube is the
// intersection of those hulls over the measurements of the beacon from the
// last one before it to the first one after it, and >= 0. Rounding included.
// (Named bathymetry_* only for the file layout of this layer: it serves any
// range-only temporal SLAM.)
#include <memory>
#include <string>
#include <vector>

#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// Stated bounds of range measurements: short and long errors, time stamps, speed.
struct RangeBounds {
  double short_err = 1.5;  // m: measured - true >= -short_err
  double long_err = 10.0;  // m: measured - true <= long_err
  double time_err = 0.2;   // s: time stamps
  double speed = 2.0;      // m/s: |z'| (the robot's speed bound)
};

std::string repr(const RangeBounds& b);

// One tube per id of `beacon_ids`, in that order, from the measurements
// (times[j], beacon[j], range[j]) (times sorted per beacon). Error on sizes,
// NaN, negative bounds, unsorted times, or a beacon id without a measurement.
TubeVector range_observation_tubes(const std::shared_ptr<TDomain>& td, const std::vector<double>& times,
                                   const std::vector<int>& beacon, const std::vector<double>& range,
                                   const std::vector<int>& beacon_ids, const RangeBounds& bounds = {});

}  // namespace sillage
