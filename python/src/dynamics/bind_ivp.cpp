// Python bindings of CtcIvp: validated integration of x' = f(x, u) as a
// tube contractor (dynamics/ctc_ivp.h), same names as in C++.
#include <pybind11/stl.h>

#include <memory>
#include <sstream>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::python {

void init_ivp(py::module_& m) {
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
      .def(
          "contract",
          [](const C& c, Tube& x) {
            py::gil_scoped_release unlocked;
            return c.contract(x);
          },
          py::arg("x"), DOC(CtcIvp, contract, Tube))
      .def(
          "contract",
          [](const C& c, TubeVector& x) {
            py::gil_scoped_release unlocked;
            return c.contract(x);
          },
          py::arg("x"), DOC(CtcIvp, contract, TubeVector))
      .def(
          "contract",
          [](const C& c, Tube& x, const Tube& u) {
            py::gil_scoped_release unlocked;
            return c.contract(x, u);
          },
          py::arg("x"), py::arg("u"), DOC(CtcIvp, contract, Tube_Tube))
      .def(
          "contract",
          [](const C& c, TubeVector& x, const TubeVector& u) {
            py::gil_scoped_release unlocked;
            return c.contract(x, u);
          },
          py::arg("x"), py::arg("u"), DOC(CtcIvp, contract, TubeVector_TubeVector))
      .def("__repr__", [](const C& c) {
        std::ostringstream os;
        os << "CtcIvp(" << c.function() << ", nb_inputs=" << c.nb_inputs() << ", order=" << c.order() << ")";
        return os.str();
      });
}

}  // namespace sillage::python
