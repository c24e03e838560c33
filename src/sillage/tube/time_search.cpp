#include "sillage/tube/time_search.h"

#include <algorithm>
#include <cmath>

namespace sillage::detail {

namespace {

// The index of t on the uniform grid from ts.front() to ts.back(), in [0, n).
std::size_t guess(std::span<const double> ts, double t) {
  const std::size_t n = ts.size();
  const double span = ts.back() - ts.front(), g = (t - ts.front()) / span * static_cast<double>(n - 1);
  if (!(g > 0)) return 0;  // NaN (a single point, a NaN time) included: any start is right
  return g >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(g);
}

// The partition point of ts for `before` (true on a prefix of ts), searched
// by doubling steps from guess(ts, t), then by bisection in the bracket found.
template <class Before>
std::size_t partition_near(std::span<const double> ts, double t, Before before) {
  const std::size_t n = ts.size();
  if (n == 0) return 0;
  std::size_t lo = 0, hi = n;  // the answer is in [lo, hi]
  std::size_t p = guess(ts, t), step = 1;
  if (before(ts[p])) {  // the answer is after p
    for (;; step *= 2) {
      const std::size_t q = n - 1 - p < step ? n : p + step;
      if (q == n || !before(ts[q])) {
        lo = p + 1;
        hi = q;
        break;
      }
      p = q;
    }
  } else {  // the answer is at p or before
    hi = p;
    for (;; step *= 2) {
      if (hi == 0) break;
      const std::size_t q = hi > step ? hi - step : 0;
      if (before(ts[q])) {
        lo = q + 1;
        break;
      }
      hi = q;
    }
  }
  return static_cast<std::size_t>(std::partition_point(ts.begin() + static_cast<std::ptrdiff_t>(lo),
                                                        ts.begin() + static_cast<std::ptrdiff_t>(hi), before) -
                                  ts.begin());
}

}  // namespace

std::size_t first_time_after(std::span<const double> ts, double t) {
  return partition_near(ts, t, [t](double v) { return !(t < v); });
}

std::size_t first_time_from(std::span<const double> ts, double t) {
  return partition_near(ts, t, [t](double v) { return v < t; });
}

}  // namespace sillage::detail
