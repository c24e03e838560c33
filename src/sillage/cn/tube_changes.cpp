#include "sillage/cn/tube_changes.h"

#include <cstring>

namespace sillage {

void TubeSnapshot::take(const Tube& x) {
  slices_.assign(x.slices().begin(), x.slices().end());
  gates_.assign(x.gates().begin(), x.gates().end());
  version_ = x.version();
}

void TubeChanges::diff(const TubeSnapshot& before, const Tube& after) const {
  if (!out_ || after.version() == before.version_) return;
  const TubeData& now = after.data();
  const std::size_t n = now.slices.size();
  // Blocks whose bytes are unchanged hold no change (a contraction often touches a few slices):
  // skipped with two memcmp; the others atom by atom, in the same order.
  constexpr std::size_t kBlock = 16;
  std::size_t k = 0;
  for (; k + kBlock <= n; k += kBlock) {
    if (std::memcmp(&before.gates_[k], &now.gates[k], kBlock * sizeof(Interval)) == 0 &&
        std::memcmp(&before.slices_[k], &now.slices[k], kBlock * sizeof(Interval)) == 0) {
      continue;
    }
    for (std::size_t i = k; i < k + kBlock; ++i) {
      gate(i, before.gates_[i], now.gates[i]);
      slice(i, before.slices_[i], now.slices[i]);
    }
  }
  for (; k <= n; ++k) {
    gate(k, before.gates_[k], now.gates[k]);
    if (k < n) slice(k, before.slices_[k], now.slices[k]);
  }
}

}  // namespace sillage
