#pragma once
// The sinusoidal tide model of thesis (7.29): the height of the sea surface
// above the chart datum z0,
//   z_tide(t) = ma sin^2((pi/2) (t - t_low) / Du),
// ma the tidal range, Du the duration of the rising tide, t_low the time of
// low water (mission seconds). height() encloses the model's value, rounding
// included; `error` bounds what the model leaves out (surge, harmonics), and
// tide(t) = height(t) + error is the rigorous tide the observation (7.30) uses.
#include <string>

#include "sillage/interval/interval.h"

namespace sillage {

// The sinusoidal tide model (7.29): ma sin^2((pi/2)(t - t_low)/Du).
struct TideModel {
  double range = 5.2;        // ma (m): a mean spring tide at Brest
  double duration = 22320;   // Du (s): 6 h 12 min
  double t_low = -5400;      // low water 1 h 30 before the dive
  Interval error = Interval(0.0);  // bounded model error (m), contains 0
  // The sea height above datum over [t], an enclosing Interval.
  Interval height(const Interval& t) const;
  // height(t) + error. Error if the error does not contain 0.
  Interval operator()(const Interval& t) const;
  double height_value(double t) const;  // plain double (truth generation, plots)
};

std::string repr(const TideModel& m);

}  // namespace sillage
