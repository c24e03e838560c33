#pragma once
// contract_local in Python, one form for the contractors on a pair of tubes
// (CtcDeriv, CtcIncrement, CtcSecondDeriv): c.contract_local(x, u, first,
// last) returns (ok, changed), `changed` the atoms of x that shrank (2k:
// gate k, 2k+1: slice k), the GIL released while it runs.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <vector>

#include "sillage/cn/tube_changes.h"
#include "sillage/tube/tube.h"

namespace sillage::python {

template <class C>
pybind11::tuple contract_local_pair(const C& c, Tube& x, const Tube& u, std::size_t first, std::size_t last) {
  std::vector<std::size_t> changed;
  bool ok = true;
  {
    pybind11::gil_scoped_release unlocked;
    ok = c.contract_local(x, u, first, last, TubeChanges(changed, 0, 0.0));
  }
  return pybind11::make_tuple(ok, changed);
}

}  // namespace sillage::python
