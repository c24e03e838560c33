// The network node of CtcPImpliesZ: cn.add(CtcPImpliesZ(eps), {p, w, z})
// with p and w 2-D or 1-D and z of any dimension, all on one TDomain. A run takes
// C_{p⇒z} to its fixed point on copies of the tubes (its own cost, the
// t-plane, dwarfs the copy) and intersects p with the result, reporting the
// slices and gates that shrank. The network's cancel token stops a run
// within one t-box.
#include <string>

#include "sillage/cn/tube_node.h"
#include "sillage/error.h"
#include "sillage/slam/ctc_p_implies_z.h"

namespace sillage {

namespace {

class PImpliesZNode : public TubeNode {
 public:
  // dim: p's (and w's) dimension, 1 or 2.
  PImpliesZNode(CtcPImpliesZ ctc, const std::vector<BoundDomain>& args, std::size_t dim)
      : TubeNode(ctc.name(), args), ctc_(std::move(ctc)) {
    if (args.size() < 2 * dim + 1) {
      throw DimensionError(where() + ": expects p (" + std::to_string(dim) + " tube(s)), w (" + std::to_string(dim) +
                           ") and z (1 tube or more), got " + std::to_string(args.size()) + " tubes");
    }
    p_ = whole_tubes(0, dim, "p");
    w_ = whole_tubes(dim, dim, "w");
    z_ = whole_tubes(2 * dim, args.size() - 2 * dim, "z");
  }

  bool run(NodeRun& r) const override {
    TubeVector p = vector_of(p_), w = vector_of(w_), z = vector_of(z_);
    ctc_.contract(p, w, z, r.cancel_token());
    for (std::size_t i = 0; i < p_.size(); ++i) {
      const Tube& pi = p[i];
      if (!contract_tube(r, i, [&](Tube& x) {
            x &= pi;
            return !x.is_empty();
          })) {
        return false;
      }
    }
    return true;
  }

 private:
  static TubeVector vector_of(const std::vector<std::shared_ptr<TubeDomain>>& d) {
    std::vector<Tube> c;
    for (const auto& x : d) c.push_back(x->tube());
    return TubeVector(std::move(c));
  }

  CtcPImpliesZ ctc_;
  std::vector<std::shared_ptr<TubeDomain>> p_, w_, z_;
};

}  // namespace

// From the flattened arguments alone: 3 or 4 tubes leave room for a 1-D p
// only, 5 or more are read as a 2-D p (p, w and z given as three tube
// vectors go through make_node_for, which knows their dimensions).
std::shared_ptr<const CnNode> CtcPImpliesZ::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<PImpliesZNode>(*this, args, args.size() < 5 ? 1 : 2);
}

std::shared_ptr<const CnNode> CtcPImpliesZ::make_node_for(const std::vector<DomainRef>& refs,
                                                           const std::vector<BoundDomain>& args) const {
  if (refs.size() != 3) return make_node(args);
  const std::size_t dim = refs[0].parts().size();
  if (dim != 1 && dim != 2) {
    throw DimensionError("ContractorNetwork::add(" + name() + "): p has " + std::to_string(dim) +
                         " components; the loop tests need a 2-D p (degree) or a 1-D p (sign change)");
  }
  if (refs[1].parts().size() != dim) {
    throw DimensionError("ContractorNetwork::add(" + name() + "): w has " + std::to_string(refs[1].parts().size()) +
                         " components, p has " + std::to_string(dim));
  }
  return std::make_shared<PImpliesZNode>(*this, args, dim);
}

}  // namespace sillage
