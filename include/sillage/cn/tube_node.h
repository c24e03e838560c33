#pragma once
// TubeNode: the one base of the network nodes that contract tubes.
//
// When to use what (a new constraint on tubes):
//  - A constraint between values at the same time, f(x(t), y(t), p) ∈ [y]:
//    write nothing tube-specific. A box contractor (Ctc, CtcFunction) given
//    tubes, cn.add(ctc, {x, y, p}), is applied at every slice and gate
//    (TubeCtcNode, a TubeNode).
//  - A contractor on whole tubes (x' = v, increments, a bias, a loop
//    implication): write its own contract(...) on its argument types and
//    derive TubeContractor (tube_contractor.h), which makes the node.
//    CtcDeriv, CtcIncrement, CtcBiasedIncrement, CtcPImpliesZ are written so.
//  - A contractor that works only where the tubes changed (CtcEval: around
//    [t]): a NetworkCtc whose make_node() returns a subclass of TubeNode,
//    whose run() contracts the domains and reports through changes() (see
//    docs/extending.md).
//  - A prototype in Python: subclass sillage.TubeCtc and override
//    contract(self, domains); cn.add(MyCtc(), [x, v]) calls it.
//
// The base owns what every tube node needs, written once:
//  - the arguments: tube(r) (null for an Interval or box argument) and
//    whole_tubes(), which checks them and names the contractor in errors;
//  - the atom encoding of a tube domain: atom 2k is gate k, atom 2k+1 is
//    slice k (gate_atom, slice_atom, is_slice, time_index, time_atom);
//  - turning the dirty atoms the network passes into what to contract again:
//    dirty_time_atoms() (a changed slice brings its two gates), dirty_slices();
//  - reporting what shrank: changes(run, r), the one TubeChanges of range r
//    (tube_changes.h), and contract_tube(), which runs a whole-tube
//    contraction, reports its changes and locates its emptiness.
//
// A node holds no mutable state: run() is const, and its scratch lives in
// run() (a node shared by two networks must not race). The one exception is
// a cache that only saves work: behind a mutex, and checked against the
// tubes before each use, so a stale or foreign entry is never trusted
// (CtcIvp's node remembers its last integration).
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/cn/tube_changes.h"
#include "sillage/cn/tube_domain.h"

namespace sillage {

// The atom encoding (gate_atom, slice_atom, is_slice, time_index, time_atom)
// is TubeAtoms' (tube/tube_atoms.h).
class TubeNode : public CnNode, public TubeAtoms {
 public:
  std::string name() const override { return name_; }

 protected:
  // `name`: the contractor's, for errors and reports; `args`: the bound
  // arguments of add(), one range each, in order.
  TubeNode(std::string name, const std::vector<BoundDomain>& args);

  // "ContractorNetwork::add(<name>)": the start of every argument error.
  std::string where() const { return "ContractorNetwork::add(" + name_ + ")"; }
  std::size_t nb_args() const { return tubes_.size(); }
  // The tube of argument r, null when it is an Interval or box argument. Its
  // tube() is the node's; its atom count is that of registration (the
  // node's ranges() say how many it has now).
  const std::shared_ptr<TubeDomain>& tube(std::size_t r) const { return tubes_[r]; }
  // Arguments [first, first + n): whole tubes (all their slices and gates)
  // on the TDomain of the node's first tube; DimensionError naming the
  // contractor and `what` otherwise.
  std::vector<std::shared_ptr<TubeDomain>> whole_tubes(std::size_t first, std::size_t n, const char* what) const;
  // Number of time atoms (2N+1) of the tubes, 0 without a tube: the count of
  // the first tube range, which grows with the tubes when the network keeps
  // the node through appends (follows_appends).
  std::size_t nb_time_atoms() const { return first_tube_ < nb_args() ? ranges()[first_tube_].count : 0; }

  // The time atoms to contract again, sorted: all on the first run, else
  // those of the tube ranges that shrank, a slice with its two gates.
  // `constants` is set when a non-tube atom is dirty (the caller decides: a
  // constant over time usually means every time element).
  std::vector<std::size_t> dirty_time_atoms(const NodeRun& run, bool& constants) const;
  // The slices first..last of tube range r holding its dirty atoms (a gate
  // brings both its slices); all of them on the first run. False if none.
  bool dirty_slices(const NodeRun& run, std::size_t r, std::size_t& first, std::size_t& last) const;

  // Reports to the network the atoms of range r that shrank.
  TubeChanges changes(NodeRun& run, std::size_t r) const { return {run.changed, offset(r), run.ratio}; }
  // Runs `contract` (false: proven empty) on the tube of range r, reports
  // what shrank, and on emptiness sets run.empty_at to the first atom from
  // which the tube's former value is inconsistent (empty_prefix.h).
  bool contract_tube(NodeRun& run, std::size_t r, const std::function<bool(Tube&)>& contract) const;
  // Empties the tubes of ranges [first, first + n) (an inconsistency found
  // on them, Lemma 5.1), reporting every slice and gate; returns false.
  bool empty_tubes(NodeRun& run, std::size_t first, std::size_t n) const;

 private:
  std::string name_;
  std::vector<std::shared_ptr<TubeDomain>> tubes_;
  std::size_t first_tube_ = static_cast<std::size_t>(-1);  // the first tube argument
};

}  // namespace sillage
