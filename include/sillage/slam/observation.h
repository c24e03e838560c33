#pragma once
// The bathymetric observation of thesis (7.29)-(7.30):
//   z = z_alt + z_depth + z_tide,  z_tide(t) = ma · sin²((π/2 · (t - t_low)) / Du) (TideModel, bathymetry_tide.h),
// the seabed height below the tide reference sensed from the robot: altitude
// (DVL or sounder) plus depth (pressure sensor) plus the tide's rise. Each
// term carries its own bounded error (the tubes of the sensors; `error` for
// the tide model). The reference level z_0 of the tide (and any constant
// sensor bias) need not be known: z(t1) = z(t2) is unchanged by a constant
// (7.4.3, Borda), so C_{p⇒z} gives the same contraction.
#include <memory>

#include "sillage/interval/interval.h"
#include "sillage/slam/bathymetry_tide.h"
#include "sillage/tube/tube.h"

namespace sillage {


// The tide as a tube on td (slice k: over [t_k, t_{k+1}]).
Tube tide_tube(const std::shared_ptr<TDomain>& td, const TideModel& tide);

// z = z_alt + z_depth + tide, slice- and gate-wise. DimensionError if the two
// sensor tubes are not on one TDomain; Error if the tide's duration does not
// exclude 0 or its error does not contain 0.
Tube bathymetric_observation(const Tube& z_alt, const Tube& z_depth, const TideModel& tide);

}  // namespace sillage
