#include "sillage/cn/cn_node.h"

#include "sillage/ctc/shrink.h"
#include "sillage/error.h"

namespace sillage {

CtcNode::CtcNode(std::shared_ptr<const Ctc> ctc, std::vector<AtomRef> atoms)
    : CnNode(std::move(atoms)), ctc_(std::move(ctc)) {
  if (!ctc_) throw Error("ContractorNetwork::add: null contractor");
  if (ctc_->nb_vars() != this->atoms().size()) {
    throw DimensionError("ContractorNetwork::add: " + ctc_->name() + " acts on " + std::to_string(ctc_->nb_vars()) +
                         " variables but the domains given add up to " + std::to_string(this->atoms().size()));
  }
}

bool CtcNode::run(const std::vector<std::shared_ptr<Domain>>& domains, double ratio,
                  std::vector<std::size_t>& changed) const {
  const auto& at = atoms();
  IntervalVector box(at.size());
  for (std::size_t k = 0; k < at.size(); ++k) box[k] = domains[at[k].domain]->atom(at[k].atom);
  const IntervalVector before(box);
  ctc_->contract(box);
  if (box.size() != before.size()) {
    throw DimensionError("ContractorNetwork: " + ctc_->name() + " changed the size of its box");
  }
  for (std::size_t k = 0; k < at.size(); ++k) {
    Domain& d = *domains[at[k].domain];
    // Read again: the same atom may appear twice in one node.
    const Interval cur = d.atom(at[k].atom);
    const Interval now = cur & box[k];
    if (now != cur) d.set_atom(at[k].atom, now);
    if (now.is_empty()) return false;
    if (shrank(before[k], now, ratio)) changed.push_back(k);
  }
  return true;
}

}  // namespace sillage
