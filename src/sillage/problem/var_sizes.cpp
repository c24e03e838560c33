#include "sillage/problem/var_sizes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "sillage/figures/thickness_figure.h"

namespace sillage {

namespace {

// An interval's width, 0 when empty (an empty box has no size), +inf when unbounded.
double width(const Interval& x) { return x.is_empty() ? 0.0 : x.diam(); }

// The diameter of a box given by its components.
template <class Get>
double diameter(std::size_t dim, const Get& get) {
  double d = 0;
  for (std::size_t i = 0; i < dim; ++i) d = std::max(d, width(get(i)));
  return d;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

std::string stats_text(const SizeStats& s, const std::string& unit) {
  const std::string u = unit.empty() ? "" : " " + unit;
  return "mean " + number(s.mean) + u + ", median " + number(s.median) + u + ", max " + number(s.max) + u;
}

}  // namespace

SizeStats size_stats(const std::vector<double>& values, const std::vector<double>& weights) {
  SizeStats s;
  s.samples = values.size();
  if (values.empty()) return s;
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  double sum = 0, below = 0;
  s.median = values[order.back()];
  bool median_found = false;
  for (const std::size_t k : order) {  // increasing: the median is where half the weight is reached
    sum += values[k] * weights[k];
    below += weights[k];
    if (!median_found && below >= total / 2) s.median = values[k], median_found = true;
  }
  s.mean = sum / total;
  s.max = values[order.back()];
  return s;
}

std::string VarSize::str() const {
  std::string s = name + ": box diameter " + stats_text(over_time, unit);
  if (over_time.samples > 1) s += " over time";
  if (at_truth) s += "; at the " + std::to_string(at_truth->samples) + " truth times " + stats_text(*at_truth, unit);
  return s;
}

std::string sizes_table(const std::vector<VarSize>& sizes) {
  std::size_t name = 8, unit = 4;
  for (const VarSize& v : sizes) name = std::max(name, v.name.size()), unit = std::max(unit, v.unit.size());
  const auto triple = [](const SizeStats& s) { return number(s.mean) + " / " + number(s.median) + " / " + number(s.max); };
  const auto cell = [](std::string s, std::size_t w) { return s.append(s.size() < w ? w - s.size() : 0, ' '); };
  std::string truth;
  for (const VarSize& v : sizes)
    if (v.at_truth) truth = "at the " + std::to_string(v.at_truth->samples) + " truth times";
  std::string out = cell("variable", name) + "  " + cell("unit", unit) + "  " + cell("over time", 30) + "  " + truth;
  while (!out.empty() && out.back() == ' ') out.pop_back();
  out += "\n";
  for (const VarSize& v : sizes) {
    std::string row = cell(v.name, name) + "  " + cell(v.unit, unit) + "  " + cell(triple(v.over_time), 30) + "  " +
                      (v.at_truth ? triple(*v.at_truth) : "");
    while (!row.empty() && row.back() == ' ') row.pop_back();
    out += row + "\n";
  }
  return out;
}

std::vector<VarSize> var_sizes(const Problem& p, const BuiltProblem& b) {
  std::vector<double> truth_times;
  if (p.output.truth) {
    const CsvTable& t = p.table(p.output.truth->data)->table;
    for (const double time : t.values(p.output.truth->time_column))
      if (time >= b.td->t0() && time <= b.td->tf()) truth_times.push_back(time);
  }
  std::vector<double> durations(b.td->nb_slices());
  for (std::size_t k = 0; k < durations.size(); ++k) durations[k] = b.td->t(k + 1) - b.td->t(k);
  std::vector<VarSize> out;
  for (const VarDomain& v : b.vars) {
    VarSize s;
    s.name = v.spec->name;
    s.unit = v.spec->unit;
    s.dim = v.spec->dim;
    if (!v.tubes) {
      const double d = v.interval ? width(*v.interval) : diameter(v.box->size(), [&](std::size_t i) { return (*v.box)[i]; });
      s.over_time = size_stats({d}, {1.0});
      out.push_back(s);
      continue;
    }
    const TubeVector& x = *v.tubes;
    // An angle's width is at most a turn (the whole circle), whatever its representative.
    const auto turn = [&](std::vector<double> w) {
      if (v.spec->angle)
        for (double& x : w) x = std::min(x, 2 * M_PI);
      return w;
    };
    s.over_time = size_stats(turn(thickness_values(x, ThicknessMeasure::MaxDiameter)), durations);
    if (p.output.truth) {
      std::vector<double> d;
      for (const double t : truth_times) d.push_back(diameter(x.size(), [&](std::size_t i) { return x[i](t); }));
      s.at_truth = size_stats(turn(d), std::vector<double>(d.size(), 1.0));
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace sillage
