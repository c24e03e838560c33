// CtcSecondDeriv (x'' ∈ [a]: each slice within the chord of its gates, bowed by
// at most [a] δ²/8): contract(x, a) on the caller's own tubes, in place; a
// NetworkCtc, so ContractorNetwork.add(CtcSecondDeriv(), [x, a]) binds it.
#include <string>

#include "bindings.h"
#include "contract_local_binding.h"
#include "docstrings.h"
#include "sillage/dynamics/ctc_second_deriv.h"

namespace sillage::python {

SILLAGE_BINDING(ctc_second_deriv, "cn", "tube") {
  py::class_<CtcSecondDeriv, NetworkCtc, std::shared_ptr<CtcSecondDeriv>>(m, "CtcSecondDeriv", R"doc(
x'' in [a](k) on every slice k: x(t) lies within the chord of its two gates, bowed by
-[a](k) tau (delta - tau) / 2 <= |[a]| delta^2 / 8, so the slices of x are contracted to
([x](t_k) | [x](t_{k+1})) - [a](k) [0, delta^2 / 8] (an acceleration bound, e.g. a turn
acceleration for a heading, is much tighter inside short slices than a rate bound).
ContractorNetwork.add(CtcSecondDeriv(), [x, a]).)doc")
      .def(py::init<>(), DOC(CtcSecondDeriv, CtcSecondDeriv))
      .def("__repr__", [](const CtcSecondDeriv&) { return std::string("CtcSecondDeriv()"); })
      .SILLAGE_DEF(CtcSecondDeriv, contract, py::arg("x"), py::arg("a"), nogil)
      // Python: returns (ok, changed), `changed` the atoms of x that shrank (2k: gate k, 2k+1: slice k).
      .def("contract_local", &contract_local_pair<CtcSecondDeriv>, py::arg("x"), py::arg("a"), py::arg("first"),
           py::arg("last"), DOC(CtcSecondDeriv, contract_local));
}

}  // namespace sillage::python
