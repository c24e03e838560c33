#pragma once
// What a tube contractor shrank, reported to the network one way for every
// node: TubeChanges receives (atom, before, after) and records the atom when
// it shrank by more than the network's ratio (shrink.h). A node gets one per
// tube argument from TubeNode::changes(); a contractor that knows what it
// changed calls gate()/slice() as it goes (CtcEval), one that does not
// compares a TubeSnapshot taken before with the tube after (CtcDeriv,
// CtcIncrement, TubeNode::contract_tube).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sillage/ctc/shrink.h"
#include "sillage/tube/tube.h"

namespace sillage {

class TubeSnapshot;

class TubeChanges {
 public:
  TubeChanges() = default;  // inactive: records nothing
  // Atom a of the tube is recorded in `out` as offset + a.
  TubeChanges(std::vector<std::size_t>& out, std::size_t offset, double ratio)
      : out_(&out), offset_(offset), ratio_(ratio) {}
  bool active() const { return out_ != nullptr; }
  void gate(std::size_t k, const Interval& before, const Interval& after) const { atom(2 * k, before, after); }
  void slice(std::size_t k, const Interval& before, const Interval& after) const { atom(2 * k + 1, before, after); }
  // Atom a in the tube encoding (TubeNode: 2k gate k, 2k+1 slice k).
  void atom(std::size_t a, const Interval& before, const Interval& after) const {
    if (out_ && after != before && shrank(before, after, ratio_)) out_->push_back(offset_ + a);
  }
  // Every slice and gate of `after` against the snapshot; nothing at all
  // when the tube was not modified (same version).
  void diff(const TubeSnapshot& before, const Tube& after) const;

 private:
  std::vector<std::size_t>* out_ = nullptr;
  std::size_t offset_ = 0;
  double ratio_ = 0.0;
};

// The slices and gates of a tube before a contraction (buffers reused by
// take()).
class TubeSnapshot {
 public:
  void take(const Tube& x);
  // The tube as it was at take(), on td (its TDomain then).
  Tube restore(const std::shared_ptr<TDomain>& td) const { return Tube(td, slices_, gates_); }

 private:
  friend class TubeChanges;
  std::vector<Interval> slices_, gates_;
  std::uint64_t version_ = 0;
};

}  // namespace sillage
