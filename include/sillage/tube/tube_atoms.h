#pragma once
// The time elements of a tube as one array: atom 2k is gate k ([x](t_k)),
// atom 2k+1 is slice k ([x](k)), 2N+1 atoms for N slices. Defined once: the
// network's TubeDomain and TubeNode inherit it, and the box contractor at
// every time (time_box_ctc.h) walks it.
#include <cstddef>

#include "sillage/tube/tube.h"

namespace sillage {

struct TubeAtoms {
  static constexpr std::size_t gate_atom(std::size_t k) { return 2 * k; }
  static constexpr std::size_t slice_atom(std::size_t k) { return 2 * k + 1; }
  static constexpr bool is_slice(std::size_t a) { return (a & 1) != 0; }
  static constexpr std::size_t time_index(std::size_t a) { return a / 2; }  // the slice or gate number
  static const Interval& time_atom(const TubeData& d, std::size_t a) {
    return is_slice(a) ? d.slices[a / 2] : d.gates[a / 2];
  }
};

}  // namespace sillage
