// LoopFunction::memoized_function: the velocity form from primitive ranges
// kept per [t], so that boxes sharing a side share the tree queries.
#include <array>
#include <bit>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "sillage/loops/loop_function.h"
#include "sillage/tube/primitive_difference.h"

namespace sillage {

namespace {

// An interval by the bits of its bounds: -0 and +0 differ, which only costs a query.
struct BoundsKey {
  std::uint64_t lo, hi;
  bool operator==(const BoundsKey&) const = default;
};

struct BoundsHash {
  std::size_t operator()(const BoundsKey& k) const {
    return std::hash<std::uint64_t>{}(k.lo * 0x9E3779B97F4A7C15ull ^ k.hi);
  }
};

using ComponentRanges = std::array<detail::PrimitiveRanges, 2>;  // per velocity component
using RangeMemo = std::unordered_map<BoundsKey, ComponentRanges, BoundsHash>;

}  // namespace

PlaneFunction LoopFunction::memoized_function() const {
  auto memo = std::make_shared<RangeMemo>();
  return [f = *this, memo](const IntervalVector& box) {
    const IntervalVector t = f.clamp(box, "LoopFunction");
    if (t.is_empty()) return f.for_zero_tests(box, IntervalVector::empty(2));
    // References into an unordered_map survive its rehashing.
    auto ranges = [&](const Interval& s) -> const ComponentRanges& {
      auto [it, fresh] = memo->try_emplace({std::bit_cast<std::uint64_t>(s.lb()), std::bit_cast<std::uint64_t>(s.ub())});
      if (fresh) {
        try {
          for (std::size_t i = 0; i < 2; ++i) f.v_[i]->ranges(s, it->second[i].lower, it->second[i].upper);
        } catch (...) {
          memo->erase(it);  // a stale tree: never keep an entry it did not fill
          throw;
        }
      }
      return it->second;
    };
    // Kept ranges are only valid for the tubes as they were: check them as a query would.
    for (const auto& tree : f.v_) tree->check_current("LoopFunction (memoized)");
    const ComponentRanges& r1 = ranges(t[0]);
    const ComponentRanges& r2 = ranges(t[1]);
    auto component = [&](std::size_t i) {
      if (f.v_[i]->has_empty_slice()) return Interval::empty();
      return detail::integral_of(detail::partial_integral_of(r1[i], r2[i]), t[0], t[1]);
    };
    return f.for_zero_tests(box, IntervalVector{component(0), component(1)});
  };
}

}  // namespace sillage
