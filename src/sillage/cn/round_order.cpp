#include "sillage/cn/round_order.h"

#include <algorithm>

namespace sillage::detail {

void RoundOrder::ran(std::size_t i, std::size_t changed, std::size_t atoms) {
  if (scheduling_ == Scheduling::Priority) share_[i] = atoms ? static_cast<double>(changed) / static_cast<double>(atoms) : 0.0;
}

void RoundOrder::order(std::vector<std::size_t>& round, const DirtyAtoms& dirty) const {
  if (scheduling_ == Scheduling::Fifo || round.size() < 2) return;
  const auto priority = [&](std::size_t i) {
    return share_[i] / static_cast<double>(std::max<std::size_t>(1, dirty.wakes(i)));
  };
  // Stable: equal priorities keep the FIFO order (deterministic).
  std::stable_sort(round.begin(), round.end(), [&](std::size_t a, std::size_t b) { return priority(a) > priority(b); });
}

}  // namespace sillage::detail
