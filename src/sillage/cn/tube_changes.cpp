#include "sillage/cn/tube_changes.h"

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
  for (std::size_t k = 0; k <= n; ++k) {
    gate(k, before.gates_[k], now.gates[k]);
    if (k < n) slice(k, before.slices_[k], now.slices[k]);
  }
}

}  // namespace sillage
