#pragma once
// The truth check of the bathymetric examples: how many samples of a true
// signal fall outside a tube, at its gates (time points that are sample
// times) and in its slices.
#include <cstddef>
#include <vector>

#include "sillage/tube/tube.h"

namespace example {

inline std::size_t truth_misses(const sillage::Tube& x, const std::vector<double>& times, const std::vector<double>& v,
                                bool slices = true) {
  const auto& td = *x.tdomain();
  std::size_t k = 0, n = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] < td.t(0) || times[i] > td.t(td.nb_slices())) continue;
    while (k + 1 < td.nb_slices() && td.t(k + 1) <= times[i]) ++k;
    if (td.t(k) == times[i] && !x.gate(k).contains(v[i])) ++n;
    if (slices && !x.slice(k).contains(v[i])) ++n;
  }
  if (td.t(td.nb_slices()) == times.back() && !x.gate(td.nb_slices()).contains(v.back())) ++n;
  return n;
}

}  // namespace example
