#pragma once
// The sinusoidal tide model of thesis (7.29): the height of the sea surface
// above the chart datum z0,
//   z_tide(t) = ma sin^2((pi/2) (t - t_low) / Du),
// ma the tidal range, Du the duration of the rising tide, t_low the time of
// low water (mission seconds). height() encloses the model's value, rounding
// included; the model error (surge, harmonics) is a stated bound apart.
#include <string>

#include "sillage/interval/interval.h"

namespace sillage {

struct TideModel {
  double range = 5.2;        // ma (m): a mean spring tide at Brest
  double duration = 22320;   // Du (s): 6 h 12 min
  double t_low = -5400;      // low water 1 h 30 before the dive
  Interval height(const Interval& t) const;
  double height_value(double t) const;  // plain double (truth generation, plots)
};

std::string repr(const TideModel& m);

}  // namespace sillage
