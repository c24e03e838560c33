// CtcBiasedIncrement (increments with one unknown constant bias b0 and an in-run
// drift): contract(x, b0, i[, j]) on the caller's own Tube and Interval, in place; a
// NetworkCtc, so ContractorNetwork.add(CtcBiasedIncrement(d_max), [x, b0, i]) binds it.
#include <string>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/dynamics/ctc_biased_increment.h"

namespace sillage::python {

SILLAGE_BINDING(ctc_biased_increment, "cn", "interval", "tube") {
  py::class_<CtcBiasedIncrement, NetworkCtc, std::shared_ptr<CtcBiasedIncrement>>(m, "CtcBiasedIncrement",
                                                                                  DOC(CtcBiasedIncrement))
      .def(py::init<double>(), py::arg("drift") = 0.0, DOC(CtcBiasedIncrement, CtcBiasedIncrement))
      .SILLAGE_DEF(CtcBiasedIncrement, drift)
      .def("__repr__",
           [](const CtcBiasedIncrement& c) {
             return "CtcBiasedIncrement(drift=" + std::string(py::repr(py::float_(c.drift()))) + ")";
           })
      .def(
          "contract",
          [](const CtcBiasedIncrement& c, Tube& x, Interval& b0, const Tube& i, Tube* j) {
            py::gil_scoped_release release;
            return j ? c.contract(x, b0, i, *j) : c.contract(x, b0, i);
          },
          py::arg("x"), py::arg("b0").noconvert(), py::arg("i"), py::arg("j") = nullptr,
          DOC(CtcBiasedIncrement, contract, Tube_Interval_Tube_Tube));
}

}  // namespace sillage::python
