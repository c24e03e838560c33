// The network node of CtcPImpliesZ: cn.add(CtcPImpliesZ(eps), {p, w, z})
// with p and w 2-D and z of any dimension, all on one TDomain. A run takes
// C_{p⇒z} to its fixed point on copies of the tubes (its own cost, the
// t-plane, dwarfs the copy) and intersects p with the result, reporting the
// slices and gates that shrank.
#include <string>

#include "sillage/cn/tube_node.h"
#include "sillage/error.h"
#include "sillage/slam/ctc_p_implies_z.h"

namespace sillage {

namespace {

class PImpliesZNode : public TubeNode {
 public:
  PImpliesZNode(CtcPImpliesZ ctc, const std::vector<BoundDomain>& args)
      : TubeNode(ctc.name(), args), ctc_(std::move(ctc)) {
    if (args.size() < 5) {
      throw DimensionError(where() + ": expects p (2 tubes), w (2 tubes) and z (1 tube or more), got " +
                           std::to_string(args.size()) + " tubes");
    }
    p_ = whole_tubes(0, 2, "p");
    w_ = whole_tubes(2, 2, "w");
    z_ = whole_tubes(4, args.size() - 4, "z");
  }

  bool run(NodeRun& r) const override {
    TubeVector p = vector_of(p_), w = vector_of(w_), z = vector_of(z_);
    ctc_.contract(p, w, z);
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

std::shared_ptr<const CnNode> CtcPImpliesZ::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<PImpliesZNode>(*this, args);
}

}  // namespace sillage
