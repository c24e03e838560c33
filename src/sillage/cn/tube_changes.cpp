#include "sillage/cn/tube_changes.h"

#include "sillage/ctc/shrink.h"

namespace sillage {

void TubeSnapshot::take(const Tube& x) {
  slices_.assign(x.slices().begin(), x.slices().end());
  gates_.assign(x.gates().begin(), x.gates().end());
  version_ = x.version();
}

void TubeSnapshot::report(const Tube& after, std::size_t offset, double ratio,
                          std::vector<std::size_t>& changed) const {
  if (after.version() == version_) return;
  const TubeData& now = after.data();
  const std::size_t n = now.slices.size();
  for (std::size_t k = 0; k <= n; ++k) {
    if (now.gates[k] != gates_[k] && shrank(gates_[k], now.gates[k], ratio)) changed.push_back(offset + 2 * k);
    if (k < n && now.slices[k] != slices_[k] && shrank(slices_[k], now.slices[k], ratio)) {
      changed.push_back(offset + 2 * k + 1);
    }
  }
}

}  // namespace sillage
