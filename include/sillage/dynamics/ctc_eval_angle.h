#pragma once
// CtcEvalAngle: z = x(t), x' = v, for an angle tube x (values known modulo
// 2π, interval/angle.h) and an uncertain time [t]: the heading at the time
// of a bearing. With [v] the hull of v over the slices meeting [t], a lift
// of the true angle gives, for every time τ near [t],
//   x(τ) ∈ z + [v] (τ - [t])        (modulo 2π)
// so, over the slices meeting [t] and their gates,
//   [z]    = angle_meet([z], [x](t_j) + [v] ([t] - t_j))   j the first and last gates
//   [x](τ) = angle_meet([x](τ), [z] + [v] (τ - [t]))      τ a gate, or a slice's time domain
// [t] itself is not contracted (a bearing's time is known; CtcEval on the
// position tube contracts it). Only the region of [t] is touched:
// CtcDerivAngle carries the rest. Without a derivative v (unbounded), only a
// [t] inside one slice contracts that slice and [z].
//
// Empty: [z] or a gate emptied sets [z] and x empty and returns false.
// In a ContractorNetwork: cn.add(ctc, {t, z, x, v}), t and z Intervals.
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/cn/tube_changes.h"
#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"

namespace sillage {

class CtcEvalAngle : public NetworkCtc {
 public:
  // The evaluation contractor on an angle tube.
  CtcEvalAngle() = default;
  std::string name() const override { return "CtcEvalAngle"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override;

  // Contracts z and the region of [t] in x. False if either is now empty.
  // [t] outside x's time domain: nothing known, true. DimensionError if x
  // and v are not on one TDomain.
  bool contract(const Interval& t, Interval& z, Tube& x, const Tube& v) const;
  // The same, reporting what shrank in x to `changes`.
  bool contract(const Interval& t, Interval& z, Tube& x, const Tube& v, const TubeChanges& changes) const;
};

}  // namespace sillage
