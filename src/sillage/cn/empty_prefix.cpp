#include "sillage/cn/empty_prefix.h"

namespace sillage::detail {

std::size_t first_empty_prefix(const Tube& x, const std::function<bool(Tube&)>& contract) {
  const std::size_t nb_atoms = 2 * x.nb_slices() + 1;
  // Atoms after `last` released to the whole line.
  const auto empty_up_to = [&](std::size_t last) {
    Tube y = x;
    {
      Tube::Writer w = y.write();
      for (std::size_t a = last + 1; a < nb_atoms; ++a) w.atom(a) = Interval();
    }
    return !contract(y);
  };
  if (!empty_up_to(nb_atoms - 1)) return nb_atoms;
  std::size_t lo = 0, hi = nb_atoms - 1;  // empty_up_to(hi) holds
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (empty_up_to(mid)) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return hi;
}

}  // namespace sillage::detail
