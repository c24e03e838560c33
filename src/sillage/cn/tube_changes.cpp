#include "sillage/cn/tube_changes.h"

#include "sillage/ctc/shrink.h"

namespace sillage {

void report_tube_changes(const TubeData& before, const Tube& after, std::size_t offset, double ratio,
                         std::vector<std::size_t>& changed) {
  const TubeData& now = after.data();
  const std::size_t n = now.slices.size();
  for (std::size_t k = 0; k <= n; ++k) {
    if (now.gates[k] != before.gates[k] && shrank(before.gates[k], now.gates[k], ratio)) {
      changed.push_back(offset + 2 * k);
    }
    if (k < n && now.slices[k] != before.slices[k] && shrank(before.slices[k], now.slices[k], ratio)) {
      changed.push_back(offset + 2 * k + 1);
    }
  }
}

}  // namespace sillage
