#pragma once
// The scheduling policy of ContractorNetwork::contract (scheduling.h): what
// each contractor did when it last ran, and the order of the next round.
#include <cstddef>
#include <vector>

#include "sillage/cn/dirty_atoms.h"
#include "sillage/cn/scheduling.h"

namespace sillage::detail {

class RoundOrder {
 public:
  RoundOrder(Scheduling s, std::size_t nb_nodes) : scheduling_(s), share_(s == Scheduling::Priority ? nb_nodes : 0, 1.0) {}
  // Node i shrank `changed` of its `atoms` atoms in its last run.
  void ran(std::size_t i, std::size_t changed, std::size_t atoms);
  // Orders the nodes of a round; dirty.wakes(i): the wake-ups of node i since
  // it last ran (its cost). Fifo: unchanged.
  void order(std::vector<std::size_t>& round, const DirtyAtoms& dirty) const;

 private:
  Scheduling scheduling_;
  std::vector<double> share_;  // per node (Priority only): the share of its atoms shrunk last time
};

}  // namespace sillage::detail
