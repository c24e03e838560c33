#pragma once
// For network nodes that contract whole tubes (CtcDeriv, CtcIncrement): the
// slices and gates of a tube before a contraction, to report to the network
// those that shrank. The buffers are reused from one run to the next.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sillage/tube/tube.h"

namespace sillage {

class TubeSnapshot {
 public:
  void take(const Tube& x);
  // Appends offset + atom (atom 2k: gate k, 2k+1: slice k) for each slice or
  // gate of `after` that shrank by more than `ratio` since take() (shrink.h);
  // nothing at all when the tube was not modified (same version).
  void report(const Tube& after, std::size_t offset, double ratio, std::vector<std::size_t>& changed) const;
  // The tube as it was at take(), on td (its TDomain then).
  Tube restore(const std::shared_ptr<TDomain>& td) const { return Tube(td, slices_, gates_); }

 private:
  std::vector<Interval> slices_, gates_;
  std::uint64_t version_ = 0;
};

}  // namespace sillage
