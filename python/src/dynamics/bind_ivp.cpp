// Python bindings of CtcIvp: validated integration of x' = f(x, u) as a
// tube contractor (dynamics/ctc_ivp.h), same names as in C++.
#include <pybind11/stl.h>

#include <memory>
#include <sstream>

#include "bindings.h"
#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/ctc_ivp.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::python {

void init_ivp(py::module_& m) {
  using C = CtcIvp;
  py::class_<C, NetworkCtc, std::shared_ptr<C>>(
      m, "CtcIvp",
      "Validated integration of x' = f(x, u) as a tube contractor (docs/ivp.md): a Taylor method of order p\n"
      "(coefficients by automatic differentiation on the expression), a Picard-Lindeloef a priori enclosure\n"
      "and Lohner's QR wrapping; forward from every bounded gate, backward from every bounded gate.\n"
      "f: a Function of the n states then the m inputs, with n outputs. In a network: cn.add(ctc, [x]) or\n"
      "cn.add(ctc, [x, u]).")
      .def(py::init<const Function&, std::size_t, int, TimePropag>(), py::arg("f"), py::arg("nb_inputs") = 0,
           py::arg("order") = 20, py::arg("time_propag") = TimePropag::FWD_BWD,
           "The contractor of x' = f(x, u); f has n outputs and n + nb_inputs variables (DimensionError\n"
           "otherwise). order: the Taylor order p (1..60).")
      .def("nb_states", &C::nb_states, "Number of states n.")
      .def("nb_inputs", &C::nb_inputs, "Number of inputs m.")
      .def("order", &C::order, "The Taylor order p.")
      .def("time_propag", &C::time_propag, "The directions of integration.")
      .def("function", &C::function, "The Function f.")
      .def("tolerance", &C::tolerance, "The bound on the last Taylor terms that sets the step length.")
      .def("set_tolerance", &C::set_tolerance, py::arg("tol"), "Sets the step tolerance (positive).")
      .def(
          "contract",
          [](const C& c, Tube& x) {
            py::gil_scoped_release unlocked;
            return c.contract(x);
          },
          py::arg("x"), "Contracts the scalar tube x in place; returns False if x is now empty.")
      .def(
          "contract",
          [](const C& c, TubeVector& x) {
            py::gil_scoped_release unlocked;
            return c.contract(x);
          },
          py::arg("x"), "Contracts the tube vector x in place; returns False if x is now empty.")
      .def(
          "contract",
          [](const C& c, Tube& x, const Tube& u) {
            py::gil_scoped_release unlocked;
            return c.contract(x, u);
          },
          py::arg("x"), py::arg("u"), "With the input tube u (any u(t) in it); returns False if x is now empty.")
      .def(
          "contract",
          [](const C& c, TubeVector& x, const TubeVector& u) {
            py::gil_scoped_release unlocked;
            return c.contract(x, u);
          },
          py::arg("x"), py::arg("u"), "With the input tube vector u; returns False if x is now empty.")
      .def("__repr__", [](const C& c) {
        std::ostringstream os;
        os << "CtcIvp(" << c.function() << ", nb_inputs=" << c.nb_inputs() << ", order=" << c.order() << ")";
        return os.str();
      });
}

}  // namespace sillage::python
