#pragma once
// A tube of per-slice values (one per odometry period, say): its gates are the
// hulls of the two neighbouring slices. They carry no information of their
// own, and per-period quantities (increments, mean rates) are not values of a
// continuous function, so neighbouring slices need not overlap.
#include <memory>
#include <vector>

#include "sillage/tube/tube.h"

namespace example {

inline sillage::Tube slice_tube(const std::shared_ptr<sillage::TDomain>& td, const std::vector<sillage::Interval>& s) {
  std::vector<sillage::Interval> g(s.size() + 1);
  for (std::size_t k = 0; k <= s.size(); ++k) g[k] = (k > 0 ? s[k - 1] : s[k]) | (k < s.size() ? s[k] : s[k - 1]);
  return sillage::Tube(td, s, g);
}

}  // namespace example
