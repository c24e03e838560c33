#pragma once
// NetworkCtc: a contractor the network binds through a node of its own kind
// (CtcDeriv, CtcEval, ...: contractors on whole tubes that are not box
// contractors). ContractorNetwork::add(ctc, {domains}) registers the domains
// and asks the contractor for the node acting on them.
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/cn_node.h"
#include "sillage/cn/domain_ref.h"
#include "sillage/tube/tdomain.h"

namespace sillage {

// A registered domain and the range of its atoms an argument covers.
struct BoundDomain {
  std::shared_ptr<Domain> domain;  // the network's domain object
  AtomRange range;                 // range.domain: its index in the network
};

class NetworkCtc {
 public:
  virtual ~NetworkCtc() = default;
  // The class name, e.g. 'CtcEval'.
  virtual std::string name() const = 0;
  // The node acting on `args` (the parts of the DomainRefs of add(), in
  // order). Throws DimensionError / Error, naming the contractor, when the
  // arguments are not what it acts on.
  virtual std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const = 0;
  // The same knowing the arguments of add() as given (refs[i] gave the next
  // refs[i].parts().size() entries of args): for a contractor whose argument
  // dimensions vary. make_node(args) by default.
  virtual std::shared_ptr<const CnNode> make_node_for(const std::vector<DomainRef>& refs,
                                                      const std::vector<BoundDomain>& args) const {
    (void)refs;
    return make_node(args);
  }

  // Times this contractor wants as time points of a TDomain before the
  // network contracts (CtcEval: the bounds of [t]); the network samples
  // them at its next contract() and rebinds its nodes. None by default.
  struct Gates {
    std::shared_ptr<TDomain> tdomain;
    std::vector<double> times;
  };
  virtual Gates gates_for(const std::vector<DomainRef>& args) const {
    (void)args;
    return {};
  }
};

}  // namespace sillage
