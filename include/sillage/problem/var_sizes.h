#pragma once
// The sizes of a solved problem's variables, in the figures a user reads:
// per variable, the diameter of its box, i.e. the largest width over its
// components (the diameter of interval analysis; a scalar's width), not the
// diagonal: it stays in the unit of the components and reads as "known to
// within d along every axis". For a tube, over time: the mean and the median
// over its slices weighted by their duration, and the max; at the truth's
// time points (the rows of [output.truth] within [t0, tf]) when the problem
// gives a truth, the tube's value at each of them. The unit is the one the
// file states ([var.NAME] unit = "m"), else none.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sillage/problem/build_network.h"

namespace sillage {

// The mean, median and max of the box diameters of one variable over a set of times (+inf: some
// box unbounded).
struct SizeStats {
  double mean = 0;    // over the slices: weighted by their duration (the mean over time)
  double median = 0;  // over the slices: weighted by their duration
  double max = 0;     // the largest
  std::size_t samples = 0;  // the slices, or the truth's time points
};

// The sizes of one variable (var_sizes).
struct VarSize {
  std::string name;  // the variable
  std::string unit;  // as the file states it ([var.NAME] unit), "" if it does not
  std::size_t dim = 1;  // its number of components
  // Tubes: over the slices, the mean and median weighted by their duration; an interval or a box:
  // its one value (samples 1).
  SizeStats over_time;
  // Tubes, when the problem gives a truth: the tube's value at each of the truth's time points.
  std::optional<SizeStats> at_truth;
  // One line: "p: box diameter mean 1.2 m, median 1.1 m, max 4.5 m over time; at the 9658 truth
  // times mean ..., median ..., max ...".
  std::string str() const;
};

// The sizes of every variable of the solved domains b of p, in the order of p.vars.
std::vector<VarSize> var_sizes(const Problem& p, const BuiltProblem& b);

// The sizes as a text table, one row per variable: name, unit, mean / median / max over time
// and at the truth's times (what sillage solve prints).
std::string sizes_table(const std::vector<VarSize>& sizes);

// The mean (weighted by `weights`, the slices' durations), weighted median and max of `values`
// (samples: their count; zeros for none).
SizeStats size_stats(const std::vector<double>& values, const std::vector<double>& weights);

}  // namespace sillage
