#pragma once
// CtcQEval: position fixes on a tube when some of them may be wrong. The
//  x(t_i) ∈ [z_i], t_i ∈ [t_i], i = 1..m, of a trajectory x with
// x' ∈ [v] are relaxed so that at most q of them may be wrong:
//   - a copy of [x] is contracted by each observation alone (CtcEval with
//     the derivative [v], which carries the fix along the whole tube);
//   - [x] is intersected, gate by gate and slice by slice, with the
//     q-relaxed intersection (q_inter) of the m copies; a copy that came out
//     empty counts as an observation violated by every trajectory of [x].
// Guarantee: a trajectory of [x] (with derivative in [v]) that satisfies at
// least m - q observations lies in the copies of those observations, so at
// each time its value is in m - q of the copies' gates / slices: it is kept.
// q = 0 is the intersection of the m CtcEval contractions; q >= m leaves [x]
// unchanged. The TDomain is never sampled (copies share it): sample it at a
// degenerate t_i beforehand for the tightest result.
//
// In a ContractorNetwork: CtcQEval(q, obs) holds its observations, and
// cn.add(ctc, {x, v}) (tube vectors, or tubes, of one size) contracts x at
// every run. The node keeps one working copy of x and records, for each
// observation, only the slices and gates its CtcEval contraction changed
// (restored before the next observation): the q-relaxed intersection of an
// atom involves only the observations that changed it, the others leaving
// it whole. Both forms keep, per atom, only the q + 1 largest lower and
// smallest upper bounds of those values, which give the q-relaxed hull
// exactly: memory (q + 1) · 16 bytes per atom, not one copy per observation.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/tube_observation.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class CtcQEval : public NetworkCtc {
 public:
  // At most q fixes are wrong; q >= 0 (else Error).
  explicit CtcQEval(int q);
  // The network form: the observations are held (a non-empty list, else Error).
  CtcQEval(int q, std::vector<TubeObservation> obs);
  // The number of fixes allowed to be wrong.
  int q() const { return q_; }
  // The fixes held for the network form (empty if none).
  const std::vector<TubeObservation>& observations() const { return obs_; }
  std::string name() const override { return "CtcQEval"; }
  // cn.add(ctc, {x, v}): needs the observations of the constructor; each z
  // and ctc of the size of x (else DimensionError naming CtcQEval).
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override;

  // Contracts x; v is its derivative (same TDomain and size, else
  // DimensionError); each z of the non-empty list obs has x.size()
  // components and each ctc acts on x.size() variables (else Error /
  // DimensionError). Returns the indices of the
  // observations that no trajectory of the input [x] satisfies (their copy
  // came out empty): if at most q observations are wrong, they are wrong.
  std::vector<std::size_t> contract(TubeVector& x, const TubeVector& v, const std::vector<TubeObservation>& obs) const;

 private:
  int q_;
  std::vector<TubeObservation> obs_;
};

}  // namespace sillage
