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
      .def("nb_states", &C::nb_states, DOC(CtcIvp, nb_states))
      .def("nb_inputs", &C::nb_inputs, DOC(CtcIvp, nb_inputs))
      .def("order", &C::order, DOC(CtcIvp, order))
      .def("time_propag", &C::time_propag, DOC(CtcIvp, time_propag))
      .def("function", &C::function, DOC(CtcIvp, function))
      .def("tolerance", &C::tolerance, DOC(CtcIvp, tolerance))
      .def("set_tolerance", &C::set_tolerance, py::arg("tol"), DOC(CtcIvp, set_tolerance))
      .def("max_pieces", &C::max_pieces, DOC(CtcIvp, max_pieces))
      .def("set_max_pieces", &C::set_max_pieces, py::arg("m"), DOC(CtcIvp, set_max_pieces))
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
