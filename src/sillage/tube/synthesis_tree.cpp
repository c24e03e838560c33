// SynthesisTree: construction, the binding to a tube, slice lookup and the
// hull queries ([x]([t]), slice_hull). The primitive part (prefix values and
// their range extrema) is in synthesis_primitive.cpp.
#include "sillage/tube/synthesis_tree.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "sillage/error.h"
#include "sillage/tube/segment_tree.h"
#include "sillage/tube/tdomain.h"

namespace sillage {

namespace {

constexpr double kInf = rounding::kInf;
constexpr std::uint64_t kInfBits = std::bit_cast<std::uint64_t>(kInf);
constexpr std::uint64_t kMinusInfBits = std::bit_cast<std::uint64_t>(-kInf);

void check_sizes(std::size_t nt, std::size_t ns, std::size_t ng) {
  if (ns == 0 || nt != ns + 1) {
    throw DimensionError("SynthesisTree: " + std::to_string(nt) + " time points for " + std::to_string(ns) +
                         " slices, expected N+1 time points and N >= 1 slices");
  }
  if (ng != 0 && ng != ns + 1) {
    throw DimensionError("SynthesisTree: " + std::to_string(ng) + " gates for " + std::to_string(ns) +
                         " slices, expected N+1 (or none)");
  }
  if (ns >= (std::size_t{1} << 31)) {
    throw DimensionError("SynthesisTree: too many slices (" + std::to_string(ns) + ")");
  }
}

}  // namespace

SynthesisTree::SynthesisTree(std::span<const double> times, std::span<const Interval> slices,
                             std::span<const Interval> gates)
    : times_(times.begin(), times.end()), slices_(slices.begin(), slices.end()), gates_(gates.begin(), gates.end()) {
  check_sizes(times.size(), slices.size(), gates.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1]))) {
      throw Error("SynthesisTree: time points must be finite and strictly increasing; t_" + std::to_string(k) +
                  " = " + number_text(times[k]));
    }
  }
  build(View{times_, slices_, gates_, nullptr});
}

SynthesisTree::SynthesisTree(std::shared_ptr<const TDomain> td, const std::shared_ptr<const TubeData>& data)
    : td_(std::move(td)), tube_(data), bound_(true) {
  if (!td_ || !data) throw Error("SynthesisTree: null TDomain or tube storage");
  check_sizes(td_->times().size(), data->slices.size(), data->gates.size());
  version_ = data->version;
  build(View{td_->times(), data->slices, data->gates, data});  // a TDomain's times are valid
}

void SynthesisTree::build(const View& d) {
  n_ = d.slices.size();
  t0_ = d.times.front();
  tf_ = d.times.back();
  inv_dt_ = static_cast<double>(n_) / (tf_ - t0_);
  has_gates_ = !d.gates.empty();
  eval_nodes_ = hull_tree(d, has_gates_);
  if (has_gates_) slice_nodes_ = hull_tree(d, false);
  build_primitive(d);
}

SynthesisTree::View SynthesisTree::view(const char* where) const {
  if (!bound_) return {times_, slices_, gates_, nullptr};
  std::shared_ptr<const TubeData> data = tube_.lock();
  if (!data) throw Error(std::string(where) + ": the tube of this synthesis tree no longer exists");
  if (data->version != version_ || data->slices.size() != n_) {
    throw Error(std::string(where) +
                ": the tube was modified since this synthesis tree was built; use its current tree "
                "(Tube::synthesis_tree)");
  }
  return {td_->times(), data->slices, data->gates, std::move(data)};
}

double SynthesisTree::t(std::size_t k) const {
  const View d = view("SynthesisTree::t(k)");
  if (k > n_) {
    throw OutOfRangeError("SynthesisTree::t(k): index " + std::to_string(k) + " out of range [0, " + std::to_string(n_) + "]");
  }
  return d.times[k];
}

Interval SynthesisTree::slice(std::size_t k) const {
  const View d = view("SynthesisTree::slice(k)");
  if (k >= n_) {
    throw OutOfRangeError("SynthesisTree::slice(k): slice " + std::to_string(k) + " out of range [0, " + std::to_string(n_) +
                ")");
  }
  return d.slices[k];
}

std::size_t SynthesisTree::slice_index(double t) const { return slice_index(view("SynthesisTree::slice_index(t)"), t); }

std::size_t SynthesisTree::slice_index(const View& d, double t) const {
  if (!(t >= t0_ && t <= tf_)) {
    throw Error("SynthesisTree::slice_index(t): t = " + number_text(t) + " is outside the domain [" +
                number_text(t0_) + ", " + number_text(tf_) + "]");
  }
  const auto ts = d.times;
  // Guess from a uniform grid, then a few steps; binary search otherwise.
  const double g = std::floor((t - t0_) * inv_dt_);
  std::size_t k = g <= 0 ? 0 : (g >= static_cast<double>(n_ - 1) ? n_ - 1 : static_cast<std::size_t>(g));
  for (int step = 0; step < 4; ++step) {
    if (ts[k] > t) {
      --k;  // k > 0 here since t_0 <= t
    } else if (k + 1 < n_ && ts[k + 1] <= t) {
      ++k;
    } else {
      return k;
    }
  }
  const auto it = std::upper_bound(ts.begin(), ts.end(), t);
  return std::min(static_cast<std::size_t>(it - ts.begin()) - 1, n_ - 1);
}

void SynthesisTree::check_interval(const Interval& t, const char* where) const {
  if (!t.is_subset(Interval(t0_, tf_))) {
    throw Error(std::string(where) + ": [t] = " + t.str() + " is not inside the domain [" + number_text(t0_) + ", " +
                number_text(tf_) + "]");
  }
}

// ---- hulls ----
// An empty interval has lb = +inf, ub = -inf: neutral for min / max.


std::vector<SynthesisTree::Hull> SynthesisTree::hull_tree(const View& d, bool with_gates) {
  const std::size_t nb = (n_ + kHullBlock - 1) / kHullBlock;
  std::vector<Hull> nodes(2 * nb, Hull{kInf, -kInf});
  for (std::size_t k = 0; k < n_; ++k) {
    Hull& h = nodes[nb + k / kHullBlock];
    h = fold_hull(h, {d.slices[k].lb(), d.slices[k].ub()});
    if (with_gates) h = fold_hull(h, {d.gates[k].lb(), d.gates[k].ub()});
  }
  detail::build_inner_nodes(nodes, [](const Hull& a, const Hull& b) { return fold_hull(a, b); });
  return nodes;
}

Interval SynthesisTree::hull(const View& d, const std::vector<Hull>& nodes, bool with_gates, std::size_t first,
                             std::size_t last) const {
  double lo = kInf, hi = -kInf;
  auto scan_array = [&](const Interval* x, std::size_t from, std::size_t to) {
    for (std::size_t k = from; k <= to; ++k) {
      lo = x[k].lb() < lo ? x[k].lb() : lo;
      hi = x[k].ub() > hi ? x[k].ub() : hi;
    }
  };
  auto scan = [&](std::size_t from, std::size_t to) {  // the leaves from..to, from the data
    scan_array(d.slices.data(), from, to);
    if (with_gates) scan_array(d.gates.data(), from, to);
  };
  Hull acc{kInf, -kInf};
  if (first <= last) {
    const std::size_t bf = first / kHullBlock, bl = last / kHullBlock;
    if (bf == bl) {
      scan(first, last);
    } else {
      scan(first, (bf + 1) * kHullBlock - 1);
      scan(bl * kHullBlock, last);
      acc = detail::fold_blocks(
          nodes, bf + 1, bl, acc, [](const Hull& a, const Hull& b) { return fold_hull(a, b); },
          [](bool take, const Hull& h) {  // h, or the empty hull, without a branch
            const std::uint64_t m = -static_cast<std::uint64_t>(take);
            return Hull{std::bit_cast<double>((std::bit_cast<std::uint64_t>(h.lo) & m) | (kInfBits & ~m)),
                        std::bit_cast<double>((std::bit_cast<std::uint64_t>(h.hi) & m) | (kMinusInfBits & ~m))};
          });
    }
  }
  acc = fold_hull(acc, {lo, hi});
  return Interval::from_bounds_unchecked(acc.lo, acc.hi);
}

Interval SynthesisTree::slice_hull(std::size_t first, std::size_t last) const {
  if (first > last) return Interval::empty();
  const View d = view("SynthesisTree::slice_hull");
  if (last >= n_) {
    throw OutOfRangeError("SynthesisTree::slice_hull: slice " + std::to_string(last) + " out of range [0, " +
                std::to_string(n_) + ")");
  }
  return hull(d, has_gates_ ? slice_nodes_ : eval_nodes_, false, first, last);
}

Interval SynthesisTree::eval(const Interval& t) const {
  if (t.is_empty()) return Interval::empty();
  check_interval(t, "SynthesisTree::eval([t])");
  const View d = view("SynthesisTree::eval([t])");
  const auto ts = d.times;
  const double a = t.lb(), b = t.ub();
  const std::size_t ka = slice_index(d, a), kb = slice_index(d, b);
  if (a == b) {
    if (a == ts[ka] || a == ts[ka + 1]) {  // a time point
      const std::size_t g = a == ts[ka] ? ka : ka + 1;
      if (has_gates_) return d.gates[g];
      return hull(d, eval_nodes_, false, g == 0 ? 0 : g - 1, std::min(g, n_ - 1));
    }
    return d.slices[ka];
  }
  // Slices meeting (a, b): ka .. last; gates with a <= t_k <= b, i.e. the
  // inner gates ka+1 .. last (one tree query with their slices), gate ka if
  // t_ka == a and gate last+1 if t_{last+1} <= b.
  const std::size_t last = (ts[kb] == b) ? kb - 1 : kb;  // kb > ka >= 0 when t_kb == b > a
  Interval r = hull(d, eval_nodes_, has_gates_, ka + 1, last) | d.slices[ka];
  if (has_gates_) {
    if (ts[ka] == a) r |= d.gates[ka];
    if (ts[last + 1] <= b) r |= d.gates[last + 1];
  }
  return r;
}

std::size_t SynthesisTree::memory_bytes() const {
  return sizeof(*this) + times_.capacity() * sizeof(double) +
         (slices_.capacity() + gates_.capacity()) * sizeof(Interval) + anchors_.capacity() * sizeof(Anchor) +
         prim_nodes_.capacity() * sizeof(Anchor) +
         (eval_nodes_.capacity() + slice_nodes_.capacity()) * sizeof(Hull) +
         (lower_counts_.capacity() + upper_counts_.capacity()) * sizeof(std::uint32_t);
}

}  // namespace sillage
