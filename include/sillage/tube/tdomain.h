#pragma once
// TDomain: the time slicing t_0 < t_1 < ... < t_N shared (std::shared_ptr) by
// all tubes of a problem, so that their slices align (thesis 3.3, design guide
// "Tubes are arrays"). Slice k is [t_k, t_{k+1}], k = 0 .. N-1; gate k is the
// value at t_k, k = 0 .. N.
//
// Refining the domain (sample(t)) refines every attached tube. Tubes attach
// their storage (TubeData) by weak reference, so a destroyed tube detaches
// itself and the domain never keeps a tube alive.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/tube/large_array.h"

namespace sillage {

// Storage of one scalar tube: N slice codomains and N+1 gates, each
// contiguous. Shared between a Tube and (weakly) its TDomain. `version`
// increases at every modification, so caches (e.g. a synthesis tree) can tell
// when to rebuild.
class SynthesisTree;

// The synthesis tree of a tube's data, built on demand and kept while the
// data does not change (see Tube::synthesis_tree). A copy starts empty: the
// copied data gets a tree of its own.
struct TreeCache {
  TreeCache() = default;
  TreeCache(const TreeCache&) {}
  TreeCache& operator=(const TreeCache&) {
    std::lock_guard<std::mutex> lock(mutex);
    tree.reset();
    return *this;
  }
  std::mutex mutex;
  std::shared_ptr<const SynthesisTree> tree;
  std::uint64_t version = 0;  // the data version the tree was built from
};

// The array of a tube's slices or gates (large ones on huge pages: large_array.h).
using TubeArray = std::vector<Interval, detail::LargeArrayAllocator<Interval>>;

struct TubeData {
  TubeArray slices;  // [x](k) over [t_k, t_{k+1}], size N
  TubeArray gates;   // [x](t_k), size N+1
  std::uint64_t version = 0;
  TreeCache tree_cache;
  // Values known modulo 2π (interval/angle.h): a gate and its slices may be
  // different turns, so nothing intersects them as real intervals.
  bool angle = false;

  void touch() { ++version; }
  // Splits slice k in two: both halves and the new gate copy the codomain.
  void split(std::size_t k);
  // One more slice and gate at the end, both the whole line (nothing known yet).
  void append();
  // Drops the first m slices and gates: gate m becomes gate 0, its value kept.
  void drop_front(std::size_t m);
};

class TDomain {
 public:
  // Uniform: t_k = t0 + k*dt, each computed directly (never accumulated);
  // the last slice may be shorter and t_N = tf exactly. Error if a bound is
  // not finite, if dt <= 0 or NaN, if tf <= t0, or if more than 2^31 slices.
  TDomain(double t0, double tf, double dt);
  // From the time points themselves (at least two, finite, strictly
  // increasing; Error otherwise, saying which index).
  explicit TDomain(std::vector<double> times);

  // Not copyable: identity matters (tubes are attached to this object).
  TDomain(const TDomain&) = delete;
  TDomain& operator=(const TDomain&) = delete;

  static std::shared_ptr<TDomain> create(double t0, double tf, double dt) {
    return std::make_shared<TDomain>(t0, tf, dt);
  }
  static std::shared_ptr<TDomain> create(std::vector<double> times) {
    return std::make_shared<TDomain>(std::move(times));
  }

  std::size_t nb_slices() const { return times_.size() - 1; }  // N
  double t(std::size_t k) const;                 // t_k, k <= N (OutOfRangeError otherwise)
  std::span<const double> times() const { return times_; }
  double t0() const { return times_.front(); }
  double tf() const { return times_.back(); }
  // [t_0, t_N] as an Interval.
  Interval t0_tf() const { return {times_.front(), times_.back()}; }

  // Index k of the slice [t_k, t_{k+1}] that contains t, in O(log N).
  // Boundary convention: at an inner time point t_k the slice that STARTS at
  // t_k is returned (k); at t_N the last slice (N-1). Error if t is NaN or
  // outside [t_0, t_N].
  std::size_t slice_index(double t) const;
  // The index k with t_k == t exactly, or -1 if t is not a time point.
  std::ptrdiff_t time_index(double t) const;
  // True if t is one of the time points t_k.
  bool is_time_point(double t) const { return time_index(t) >= 0; }

  Interval slice_domain(std::size_t k) const;  // [t_k, t_{k+1}], OutOfRangeError if k >= N
  // Rigorous width t_{k+1} - t_k: Interval(t_{k+1}) - Interval(t_k), outward
  // (OutOfRangeError if k >= N).
  Interval slice_width(std::size_t k) const;

  // Adds the time point t (inside (t_0, t_N)) and splits, in every attached
  // tube, the slice that contains it: both halves copy the slice codomain and
  // the new gate is that codomain. No-op if t is already a time point.
  // Returns the index of the time point t. Error if t is NaN or outside.
  // Not to be called while other threads use this domain or its tubes.
  std::size_t sample(double t);
  // Adds both bounds of t as time points (those strictly inside (t_0, t_N)
  // that are not already), e.g. the time interval of an observation, so
  // that the tube holds the values at its ends as gates (CtcEval is then as
  // tight inside those slices as the definition allows). Empty t: nothing.
  // Error if t does not meet [t_0, t_N].
  // Same threading rule as sample(double).
  void sample(const Interval& t);

  // Online estimation (docs/online.md): the domain grows as time advances
  // and forgets the past beyond a window. Same threading rule as sample().
  //
  // Appends the time point t > t_N: every attached tube gains a slice
  // [t_N, t] and a gate at t, both the whole line (nothing is known of the
  // future until a contractor says so). Returns the new N. Error if t is not
  // finite or not after t_N.
  std::size_t extend(double t);
  // Drops the slices that end at or before t (never the last one): every
  // attached tube loses them, and its gate at the new t_0 keeps its value, an
  // enclosure proven with the past. Returns the number of slices dropped (0 if
  // t <= t_1). Error if t is NaN.
  std::size_t forget_before(double t);
  // Slices dropped by forget_before since the domain was made: slice k of
  // today was slice nb_forgotten() + k of the first day.
  std::size_t nb_forgotten() const { return forgotten_; }

  // Number of tubes (scalar components) currently attached and alive.
  std::size_t nb_attached() const;

  // Used by Tube: registers the storage of a tube, once per storage (sizes
  // must match; DimensionError otherwise). sample() then splits it.
  void attach(const std::shared_ptr<TubeData>& data);

 private:
  std::vector<double> times_;
  mutable std::mutex mutex_;  // guards attached_ (tubes may be copied concurrently)
  mutable std::vector<std::weak_ptr<TubeData>> attached_;
  std::size_t prune_at_ = 16;  // next size at which expired entries are purged
  std::size_t forgotten_ = 0;  // forget_before
  // Calls f(data) for every attached tube alive, purging the dead (mutex_ held).
  template <class F>
  void for_each_attached(F&& f);
};

// The slices k of td whose domain meets the interior of t (t non-empty, with
// positive width), or that contain t when it is degenerate: first..last.
// Error if t is empty or not inside [t_0, t_N].
void slice_range(const TDomain& td, const Interval& t, std::size_t& first, std::size_t& last, const char* where);

}  // namespace sillage
