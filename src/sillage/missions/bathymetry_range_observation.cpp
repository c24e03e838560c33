#include "sillage/missions/bathymetry_range_observation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sillage/error.h"

namespace sillage {

std::string repr(const RangeBounds& b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "RangeBounds(short_err=%g m, long_err=%g m, time_err=%g s, speed=%g m/s)",
                b.short_err, b.long_err, b.time_err, b.speed);
  return buf;
}

namespace {

// The hull over t in [a, b] of the enclosure given by measurement (tj, rj).
Interval from_measurement(double a, double b, double tj, double rj, const RangeBounds& rb) {
  const Interval reach = Interval(rb.speed) * (max(abs(Interval(a) - Interval(tj)), abs(Interval(b) - Interval(tj))) +
                                               Interval(rb.time_err));
  const double r = reach.ub();
  return Interval((Interval(rj) - Interval(rb.long_err)).lb(), (Interval(rj) + Interval(rb.short_err)).ub()) +
         Interval(-r, r);
}

}  // namespace

TubeVector range_observation_tubes(const std::shared_ptr<TDomain>& td, const std::vector<double>& times,
                                   const std::vector<int>& beacon, const std::vector<double>& range,
                                   const std::vector<int>& beacon_ids, const RangeBounds& rb) {
  const char* where = "range_observation_tubes";
  if (!td) throw Error(std::string(where) + ": null TDomain");
  if (times.size() != beacon.size() || times.size() != range.size())
    throw DimensionError(std::string(where) + ": times, beacon and range must have the same size (" +
                         std::to_string(times.size()) + ", " + std::to_string(beacon.size()) + ", " +
                         std::to_string(range.size()) + ")");
  for (double v : {rb.short_err, rb.long_err, rb.time_err, rb.speed})
    if (!(v >= 0) || !std::isfinite(v)) throw Error(std::string(where) + ": the bounds must be finite and >= 0");
  if (beacon_ids.empty()) throw DimensionError(std::string(where) + ": no beacon id");
  std::vector<Tube> tubes;
  const std::size_t N = td->nb_slices();
  for (int id : beacon_ids) {
    std::vector<double> ts, rs;
    for (std::size_t j = 0; j < times.size(); ++j) {
      if (beacon[j] != id) continue;
      if (!std::isfinite(times[j]) || !std::isfinite(range[j]))
        throw Error(std::string(where) + ": measurement " + std::to_string(j) + " is not finite");
      if (!ts.empty() && times[j] < ts.back())
        throw Error(std::string(where) + ": times not sorted at measurement " + std::to_string(j));
      ts.push_back(times[j]), rs.push_back(range[j]);
    }
    if (ts.empty()) throw Error(std::string(where) + ": no measurement of beacon " + std::to_string(id));
    // Measurements from the last one before [a, b] to the first one after it.
    auto enclose = [&](double a, double b) {
      const auto first = std::lower_bound(ts.begin(), ts.end(), a);
      const auto last = std::upper_bound(ts.begin(), ts.end(), b);
      std::size_t j0 = static_cast<std::size_t>(first - ts.begin()), j1 = static_cast<std::size_t>(last - ts.begin());
      if (j0 > 0) --j0;
      if (j1 == ts.size()) --j1;
      Interval z = Interval::pos_reals();
      for (std::size_t j = j0; j <= j1; ++j) z &= from_measurement(a, b, ts[j], rs[j], rb);
      return z;
    };
    std::vector<Interval> slices(N), gates(N + 1);
    for (std::size_t k = 0; k <= N; ++k) gates[k] = enclose(td->t(k), td->t(k));
    for (std::size_t k = 0; k < N; ++k) slices[k] = enclose(td->t(k), td->t(k + 1));
    // The measurements are inconsistent if a gate or slice is empty: say where.
    for (std::size_t k = 0; k < N; ++k)
      if (slices[k].is_empty())
        throw Error(std::string(where) + ": beacon " + std::to_string(id) + ": the measurements around t = " +
                    std::to_string(td->t(k)) + " s contradict each other under " + repr(rb));
    tubes.emplace_back(td, slices, gates);
  }
  return TubeVector(std::move(tubes));
}

}  // namespace sillage
