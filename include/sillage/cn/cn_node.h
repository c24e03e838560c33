#pragma once
// CnNode: a contractor bound to ranges of atoms of the network's domains.
// The network wakes a node when one of its atoms shrank, and tells it which
// ones (NodeRun::dirty), so that a node acting on tubes re-contracts only the
// slices that changed. run() contracts the domains and reports which of its
// atoms shrank by more than the ratio.
//
// Atoms of a node are numbered by position: the concatenation of its ranges.
// CtcNode binds a box contractor (Ctc) on few atoms; nodes on tubes derive
// from TubeNode (tube_node.h): TubeCtcNode applies a box contractor at every
// slice and gate, TubeContractor's node runs a contractor on whole tubes
// (CtcDeriv, CtcIncrement, ...), and
// dynamics/ adds the CtcEval node.
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/cn/domain.h"
#include "sillage/ctc/ctc.h"

namespace sillage {

namespace detail {
class ContractorNetworkImpl;
}

// Atoms [first, first + count) of the network's domain number `domain`.
struct AtomRange {
  std::size_t domain;
  std::size_t first;
  std::size_t count;
};

// Tube ranges x and v on which a node enforces x' = v over the whole tube
// (CtcDeriv's node): other nodes may leave that propagation to it.
struct DerivativePair {
  AtomRange x, v;
};

// What one run of a node gets from the network, and gives back.
struct NodeRun {
  const std::vector<std::shared_ptr<Domain>>& domains;
  double ratio;
  // True on the first run of a contract(): everything is to be contracted.
  bool all;
  // Otherwise: positions of the node's atoms that shrank since its last run
  // (sorted, no duplicates).
  std::span<const std::size_t> dirty;
  // Out: positions of the atoms this run shrank by more than `ratio`
  // (shrink.h); duplicates allowed.
  std::vector<std::size_t>& changed;
  // Out, when run() returns false, if the node knows it: the position of the
  // atom where it found the emptiness (else the network reports the first
  // empty atom of the node), and the time it concerns (CtcEval's [t]).
  std::size_t empty_at = kNoAtom;
  Interval empty_time = Interval::empty();
  // Out: run this node again in the next round even if nothing else wakes it
  // (a node that stopped short of its own fixed point: CtcEval after one pass
  // that shrank something, so that its confirming pass merges with the next
  // wake-up by its neighbours).
  bool again = false;
  // The pairs of the network's nodes (CnNode::derivative_pairs), so that a
  // node can leave to them what they do anyway (CtcEval: its fronts beyond [t]).
  std::span<const DerivativePair> derivatives = {};
  // Whether a node of the network enforces x' = v over the whole tubes x, v.
  bool has_derivative(const AtomRange& x, const AtomRange& v) const;
  // The network's cancel token (its budget's; null: none), for a node that
  // runs long (CtcIvp, CtcPImpliesZ) to pass on, so that a cancelled
  // contract() stops within the node.
  const CancelToken* cancel = nullptr;
  // *cancel, or a token that is never cancelled.
  const CancelToken& cancel_token() const;
};

class CnNode {
 public:
  explicit CnNode(std::vector<AtomRange> ranges);
  virtual ~CnNode() = default;
  virtual std::string name() const = 0;
  // For reports (emptiness): the name and what tells this node from others.
  virtual std::string describe() const { return name(); }
  const std::vector<AtomRange>& ranges() const { return ranges_; }
  std::size_t nb_atoms() const { return nb_atoms_; }
  // Position of the first atom of range r.
  std::size_t offset(std::size_t r) const { return offsets_[r]; }
  // The range holding position pos (< nb_atoms()).
  std::size_t range_of(std::size_t pos) const;
  // The atoms whose shrinking wakes this node: its ranges, unless narrowed
  // by watch_only (one entry per range, a sub-range of it; count 0: none).
  const std::vector<AtomRange>& watched() const { return watched_; }
  // Contracts the domains. Returns false as soon as a domain became empty.
  virtual bool run(NodeRun& r) const = 0;
  // Appends the tube ranges (x, v) on which run() enforces x' = v over the
  // whole tube, to fixed point (CtcDeriv's node); none by default.
  virtual void derivative_pairs(std::vector<DerivativePair>& /*out*/) const {}
  // Whether the node stays right when a tube it acts on gains slices at its
  // end (TDomain::extend) or loses them at its start (TDomain::forget_before),
  // its ranges over that whole tube following it (a range over part of it
  // moving with its slices): nothing in it depends on the number of slices
  // or on their indices. The network then keeps it rather than building it
  // anew (online estimation). False by default.
  virtual bool follows_appends() const { return false; }

 protected:
  // Wakes this node only for atoms [first, first + count) of range r (a node
  // whose contraction depends on part of a domain, e.g. CtcEval on the
  // slices around [t]). Waking less never loses a solution.
  void watch_only(std::size_t r, std::size_t first, std::size_t count);

 private:
  std::vector<AtomRange> ranges_;
  std::vector<AtomRange> watched_;
  std::vector<std::size_t> offsets_;
  std::size_t nb_atoms_ = 0;

  friend class detail::ContractorNetworkImpl;
  // The ranges (and watched ranges) covering the from[d] atoms of a domain d
  // that grew (kNoAtom: it did not) now cover its domains[d]->nb_atoms()
  // (the network, for a node that follows_appends()). True if a watched
  // range grew with them.
  bool follow_appends(const std::vector<std::size_t>& from, const std::vector<std::shared_ptr<Domain>>& domains);
  // The same when the domains also dropped atoms at their start (dropped[d]
  // of them: a TDomain that forgot its past): a range over a whole domain
  // covers it whole again, a range over part of it moves back by dropped[d],
  // cut where it began before the new start.
  void follow_shift(const std::vector<std::size_t>& from, const std::vector<std::size_t>& dropped,
                    const std::vector<std::shared_ptr<Domain>>& domains);
  // The ranges' domains renumbered: domain d is now index[d] (the network
  // dropped the domains no node uses any more).
  void renumber_domains(const std::vector<std::size_t>& index);
  // offsets_ and nb_atoms_ from the ranges.
  void count_atoms();
};

// A box contractor on the concatenation of its atoms: read, contract, write
// back intersected (so even a contractor that would enlarge cannot). Runs on
// its whole box whatever changed.
class CtcNode : public CnNode {
 public:
  CtcNode(std::shared_ptr<const Ctc> ctc, std::vector<AtomRange> ranges);
  std::string name() const override { return ctc_->name(); }
  std::string describe() const override { return ctc_->describe(); }
  bool run(NodeRun& r) const override;
  const std::shared_ptr<const Ctc>& ctc() const { return ctc_; }

 private:
  std::shared_ptr<const Ctc> ctc_;
};

}  // namespace sillage
