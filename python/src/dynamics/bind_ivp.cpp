// Python bindings of CtcIvp: validated integration of x' = f(x, u) as a
// tube contractor (dynamics/ctc_ivp.h), same names as in C++.
#include <pybind11/stl.h>

#include <memory>
#include <sstream>

#include "bindings.h"
#include "docstrings.h"
#include "interruptible.h"
#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::python {

SILLAGE_BINDING(ivp, "budget", "cn", "dynamics", "expr", "tube") {
  using C = CtcIvp;
  py::class_<C, NetworkCtc, std::shared_ptr<C>>(
      m, "CtcIvp",
      DOC(CtcIvp))
      .def(py::init<const Function&, std::size_t, int, TimePropag>(), py::arg("f"), py::arg("nb_inputs") = 0,
           py::arg("order") = 20, py::arg("time_propag") = TimePropag::FWD_BWD,
           DOC(CtcIvp, CtcIvp))
      .SILLAGE_DEFS(CtcIvp, nb_states, nb_inputs, order, time_propag, function, tolerance)
      .SILLAGE_DEF(CtcIvp, set_tolerance, py::arg("tol"))
      .SILLAGE_DEF(CtcIvp, max_pieces)
      .SILLAGE_DEF(CtcIvp, set_max_pieces, py::arg("m"))
      // On a worker thread: Ctrl-C (or `cancel`) stops it within an integration step.
      .def(
          "contract",
          [](const C& c, Tube& x, const CancelToken* cancel) {
            return run_interruptible(cancel, [&](const CancelToken& t) { return c.contract(x, t); });
          },
          py::arg("x"), py::arg("cancel") = nullptr, DOC(CtcIvp, contract, Tube_CancelToken))
      .def(
          "contract",
          [](const C& c, TubeVector& x, const CancelToken* cancel) {
            return run_interruptible(cancel, [&](const CancelToken& t) { return c.contract(x, t); });
          },
          py::arg("x"), py::arg("cancel") = nullptr, DOC(CtcIvp, contract, TubeVector_CancelToken))
      .def(
          "contract",
          [](const C& c, Tube& x, const Tube& u, const CancelToken* cancel) {
            return run_interruptible(cancel, [&](const CancelToken& t) { return c.contract(x, u, t); });
          },
          py::arg("x"), py::arg("u"), py::arg("cancel") = nullptr, DOC(CtcIvp, contract, Tube_Tube_CancelToken))
      .def(
          "contract",
          [](const C& c, TubeVector& x, const TubeVector& u, const CancelToken* cancel) {
            return run_interruptible(cancel, [&](const CancelToken& t) { return c.contract(x, u, t); });
          },
          py::arg("x"), py::arg("u"), py::arg("cancel") = nullptr,
          DOC(CtcIvp, contract, TubeVector_TubeVector_CancelToken))
      .def("__repr__", [](const C& c) {
        std::ostringstream os;
        os << "CtcIvp(" << c.function() << ", nb_inputs=" << c.nb_inputs() << ", order=" << c.order() << ")";
        return os.str();
      });
}

}  // namespace sillage::python
