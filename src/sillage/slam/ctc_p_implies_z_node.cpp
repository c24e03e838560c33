// CtcPImpliesZ in a network: cn.add(CtcPImpliesZ(eps), {p, w, z}) with p and
// w 2-D or 1-D and z of any dimension, all on one TDomain. The node
// (TubeContractor) runs contract(p, w, z) to its fixed point on copies of the
// tubes (its own cost, the t-plane, dwarfs the copy) and intersects p with the
// result; the network's cancel token stops a run within one t-box.
#include <string>

#include "sillage/error.h"
#include "sillage/slam/ctc_p_implies_z.h"

namespace sillage {

// From the flattened arguments alone: 3 or 4 tubes leave room for a 1-D p
// only, 5 or more are read as a 2-D p (p, w and z given as three tube
// vectors go through make_node_for, which knows their dimensions).
std::shared_ptr<const CnNode> CtcPImpliesZ::make_node(const std::vector<BoundDomain>& args) const {
  const std::size_t dim = args.size() < 5 ? 1 : 2;
  if (args.size() < 2 * dim + 1) {
    throw DimensionError("ContractorNetwork::add(" + name() + "): expects p (" + std::to_string(dim) +
                         " tube(s)), w (" + std::to_string(dim) + ") and z (1 tube or more), got " +
                         std::to_string(args.size()) + " tubes");
  }
  return make_node_split(args, {dim, dim, args.size() - 2 * dim});
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
  return TubeContractor::make_node_for(refs, args);
}

}  // namespace sillage
