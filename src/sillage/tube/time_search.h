#pragma once
// Where a time falls among the increasing time points of a TDomain
// (internal header): std::upper_bound / std::lower_bound with the same
// results, started from the index the time would have on a uniform grid and
// widened by doubling steps. Most domains are uniform or nearly so: the
// answer is then found in a step or two instead of log2(N) scattered reads
// over the whole array (a cache miss each on long domains).
#include <cstddef>
#include <span>

namespace sillage::detail {

// The first k with ts[k] > t (ts.size() if none), as std::upper_bound.
std::size_t first_time_after(std::span<const double> ts, double t);
// The first k with ts[k] >= t (ts.size() if none), as std::lower_bound.
std::size_t first_time_from(std::span<const double> ts, double t);

}  // namespace sillage::detail
