// CtcEval (thesis Prop. 5.1) and CtcIncrement (odometry increments): contract(t, z, y, w) on the caller's own
// Interval / IntervalVector / Tube / TubeVector objects, in place; a
// NetworkCtc, so ContractorNetwork.add(CtcEval(), [t, z, y, w]) binds it.
#include "bindings.h"
#include "contract_local_binding.h"
#include "docstrings.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_increment.h"

namespace sillage::python {

SILLAGE_BINDING(ctc_eval, "cn", "interval", "tube") {
  py::class_<CtcEval, NetworkCtc, std::shared_ptr<CtcEval>>(
      m, "CtcEval",
      DOC(CtcEval))
      .def(py::init<>(), DOC(CtcEval, CtcEval))
      .SILLAGE_DEF(CtcEval, enable_time_sampling, py::arg("on"))
      .SILLAGE_DEF(CtcEval, time_sampling)
      .SILLAGE_DEF(CtcEval, enable_gates_at_time_bounds, py::arg("on"))
      .SILLAGE_DEF(CtcEval, gates_at_time_bounds)
      .def(
          "contract",
          [](const CtcEval& c, Interval& t, Interval& z, Tube& y, const Tube* w) {
            return w ? c.contract(t, z, y, *w) : c.contract(t, z, y);
          },
          py::arg("t").noconvert(), py::arg("z").noconvert(), py::arg("y"), py::arg("w") = nullptr,
          DOC(CtcEval, contract, Interval_Interval_Tube_Tube))
      .def(
          "contract",
          [](const CtcEval& c, Interval& t, IntervalVector& z, TubeVector& y, const TubeVector* w) {
            return w ? c.contract(t, z, y, *w) : c.contract(t, z, y);
          },
          py::arg("t").noconvert(), py::arg("z").noconvert(), py::arg("y"), py::arg("w") = nullptr,
          DOC(CtcEval, contract, Interval_IntervalVector_TubeVector_TubeVector));

  py::class_<CtcIncrement, NetworkCtc, std::shared_ptr<CtcIncrement>>(
      m, "CtcIncrement",
      DOC(CtcIncrement))
      .def(py::init<>(), DOC(CtcIncrement, CtcIncrement))
      .def("contract", py::overload_cast<Tube&, const Tube&>(&CtcIncrement::contract, py::const_), py::arg("x"),
           py::arg("i"),
           DOC(CtcIncrement, contract, Tube_Tube))
      .def("contract", py::overload_cast<TubeVector&, const TubeVector&>(&CtcIncrement::contract, py::const_),
           py::arg("x"), py::arg("i"), DOC(CtcIncrement, contract, TubeVector_TubeVector))
      // Python: returns (ok, changed), `changed` the atoms of x that shrank (2k: gate k, 2k+1: slice k).
      .def("contract_local", &contract_local_pair<CtcIncrement>, py::arg("x"), py::arg("i"), py::arg("first"),
           py::arg("last"), DOC(CtcIncrement, contract_local));
}

}  // namespace sillage::python
