// Python bindings of the dynamics layer: TimePropag, CtcDeriv (x' = v on
// Tubes and TubeVectors, in place), and the derivative forms of Tube.eval and
// Tube.inverse (added to the Tube class registered in bind_tube.cpp).
#include <pybind11/stl.h>

#include <memory>

#include "bindings.h"
#include "contract_local_binding.h"
#include "docstrings.h"
#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/time_propag.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::python {

SILLAGE_BINDING(dynamics, "cn", "interval", "tube") {
  py::enum_<TimePropag>(m, "TimePropag", DOC(TimePropag))
      .value("FORWARD", TimePropag::FORWARD)
      .value("BACKWARD", TimePropag::BACKWARD)
      .value("FWD_BWD", TimePropag::FWD_BWD)
      .def("__or__", [](TimePropag a, TimePropag b) { return a | b; }, py::is_operator());

  using C = CtcDeriv;
  py::class_<C, NetworkCtc, std::shared_ptr<C>>(m, "CtcDeriv", DOC(CtcDeriv))
      .def(py::init<TimePropag>(), py::arg("time_propag") = TimePropag::FWD_BWD, DOC(CtcDeriv, CtcDeriv))
      .SILLAGE_DEFS(CtcDeriv, time_propag, enforces_derivative)
      .def("contract", py::overload_cast<Tube&, const Tube&>(&C::contract, py::const_), py::arg("x"), py::arg("v"),
           nogil, DOC(CtcDeriv, contract, Tube_Tube))
      .def("contract", py::overload_cast<Tube&, const Tube&, std::size_t, std::size_t>(&C::contract, py::const_),
           py::arg("x"), py::arg("v"), py::arg("first"), py::arg("last"), nogil,
           DOC(CtcDeriv, contract, Tube_Tube_size_t_size_t))
      .def("contract", py::overload_cast<Tube&, const Tube&, const Interval&>(&C::contract, py::const_), py::arg("x"),
           py::arg("v"), py::arg("t"), nogil, DOC(CtcDeriv, contract, Tube_Tube_Interval))
      .def("contract", py::overload_cast<TubeVector&, const TubeVector&>(&C::contract, py::const_), py::arg("x"),
           py::arg("v"), nogil, DOC(CtcDeriv, contract, TubeVector_TubeVector))
      .def("contract",
           py::overload_cast<TubeVector&, const TubeVector&, std::size_t, std::size_t>(&C::contract, py::const_),
           py::arg("x"), py::arg("v"), py::arg("first"), py::arg("last"), nogil,
           DOC(CtcDeriv, contract, TubeVector_TubeVector_size_t_size_t))
      .def("contract", py::overload_cast<TubeVector&, const TubeVector&, const Interval&>(&C::contract, py::const_),
           py::arg("x"), py::arg("v"), py::arg("t"), nogil, DOC(CtcDeriv, contract, TubeVector_TubeVector_Interval))
      // Python: returns (ok, changed), `changed` the atoms that shrank (2k: gate k, 2k+1: slice k).
      .def("contract_local", &contract_local_pair<C>, py::arg("x"), py::arg("v"), py::arg("first"), py::arg("last"),
           DOC(CtcDeriv, contract_local))
      .def("__repr__", [](const C& c) {
        switch (c.time_propag()) {
          case TimePropag::FORWARD:
            return std::string("CtcDeriv(TimePropag.FORWARD)");
          case TimePropag::BACKWARD:
            return std::string("CtcDeriv(TimePropag.BACKWARD)");
          case TimePropag::FWD_BWD:
            break;
        }
        return std::string("CtcDeriv(TimePropag.FWD_BWD)");
      });

  // Tube.eval(t, v) and Tube.inverse(y, v): overloads added to the class of
  // bind_tube.cpp (def chains them with the existing "inverse").
  auto tube = py::reinterpret_borrow<py::class_<Tube, std::shared_ptr<Tube>>>(m.attr("Tube"));
  tube.def("eval", &Tube::eval, py::arg("t"), py::arg("v"),
           "Hull of x over the time (interval) t, read through the derivative tube v: in each slice the\n"
           "polygon ([x](t_k) + (t-t_k)[v]) & ([x](t_k+1) - (t_k+1-t)[v]) & [x](k), tighter than x(t).")
      .def("inverse", py::overload_cast<const Interval&, const Tube&>(&Tube::inverse, py::const_), py::arg("y"),
           py::arg("v"), "Hull of the times where the polygon of x with derivative v meets y (within x.inverse(y)).")
      .def("inverse",
           py::overload_cast<const Interval&, const Tube&, const Interval&>(&Tube::inverse, py::const_),
           py::arg("y"), py::arg("v"), py::arg("t"), "The same, restricted to the times t (a subset of t).")
      .def("memory_bytes", &Tube::memory_bytes, "Bytes held: slices, gates and the cached synthesis tree.");
}

}  // namespace sillage::python
