#pragma once
// The node of a contractor on pairs of tubes, x and v with as many
// components: cn.add(ctc, {x, v}) with tubes, tube components or tube
// vectors (x first). C needs `std::string name() const` and
// `bool contract(Tube& x, const Tube& v) const` (false: x proven empty);
// its make_node() is then one line:
//   return make_tube_pair_node(*this, args);
// Each run contracts every x[i] with v[i] as a whole, reports the slices and
// gates that shrank and, on emptiness, where x stopped being consistent.
// A C with `bool enforces_derivative() const` returning true (CtcDeriv with
// both sweeps) tells the network that its node enforces x' = v
// (derivative_pairs).
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/tube_node.h"
#include "sillage/error.h"

namespace sillage {

template <class C>
class TubePairNode : public TubeNode {
 public:
  TubePairNode(C ctc, const std::vector<BoundDomain>& args) : TubeNode(ctc.name(), args), ctc_(std::move(ctc)) {
    if (args.empty() || args.size() % 2 != 0) {
      throw DimensionError(where() + ": expects x and v with as many components, got " + std::to_string(args.size()) +
                           " tubes");
    }
    x_ = whole_tubes(0, args.size() / 2, "x");
    v_ = whole_tubes(args.size() / 2, args.size() / 2, "v");
  }
  bool run(NodeRun& r) const override {
    for (std::size_t i = 0; i < x_.size(); ++i) {
      const Tube& v = v_[i]->tube();
      if (!contract_tube(r, i, [&](Tube& x) { return ctc_.contract(x, v); })) return false;
    }
    return true;
  }
  void derivative_pairs(std::vector<DerivativePair>& out) const override {
    if constexpr (requires(const C& c) { c.enforces_derivative(); }) {
      if (!ctc_.enforces_derivative()) return;
      for (std::size_t i = 0; i < x_.size(); ++i) out.push_back({ranges()[i], ranges()[x_.size() + i]});
    }
  }

 private:
  C ctc_;
  std::vector<std::shared_ptr<TubeDomain>> x_, v_;
};

template <class C>
std::shared_ptr<const CnNode> make_tube_pair_node(const C& ctc, const std::vector<BoundDomain>& args) {
  return std::make_shared<TubePairNode<C>>(ctc, args);
}

}  // namespace sillage
