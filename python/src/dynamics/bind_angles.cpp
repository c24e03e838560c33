// Angles known modulo 2π (interval/angle.h): angle_meet, angle_contains,
// angle_is_circle; the contractors on angle tubes CtcDerivAngle (x' = v) and
// CtcEvalAngle (z = x(t)), NetworkCtc both; and CtcAngleEquation, a box
// contractor (a bearing from a heading, wrapping automatic).
#include <pybind11/stl.h>

#include <string>

#include "bindings.h"
#include "contract_local_binding.h"
#include "docstrings.h"
#include "sillage/ctc/ctc_angle_equation.h"
#include "sillage/dynamics/ctc_deriv_angle.h"
#include "sillage/dynamics/ctc_eval_angle.h"
#include "sillage/interval/angle.h"

namespace sillage::python {

SILLAGE_BINDING(angles, "cn", "ctc", "expr", "interval", "tube") {
  m.SILLAGE_FN(angle_meet, py::arg("x"), py::arg("y"));
  m.SILLAGE_FN(angle_contains, py::arg("x"), py::arg("a"));
  m.SILLAGE_FN(angle_is_circle, py::arg("x"));

  py::class_<CtcDerivAngle, NetworkCtc, std::shared_ptr<CtcDerivAngle>>(m, "CtcDerivAngle", DOC(CtcDerivAngle))
      .def(py::init<>(), DOC(CtcDerivAngle, CtcDerivAngle))
      .def("__repr__", [](const CtcDerivAngle&) { return std::string("CtcDerivAngle()"); })
      .SILLAGE_DEF(CtcDerivAngle, contract, py::arg("x"), py::arg("v"), nogil)
      // Python: returns (ok, changed), `changed` the atoms of x that shrank (2k: gate k, 2k+1: slice k).
      .def("contract_local", &contract_local_pair<CtcDerivAngle>, py::arg("x"), py::arg("v"), py::arg("first"),
           py::arg("last"), DOC(CtcDerivAngle, contract_local));

  py::class_<CtcEvalAngle, NetworkCtc, std::shared_ptr<CtcEvalAngle>>(m, "CtcEvalAngle", DOC(CtcEvalAngle))
      .def(py::init<>(), DOC(CtcEvalAngle, CtcEvalAngle))
      .def("__repr__", [](const CtcEvalAngle&) { return std::string("CtcEvalAngle()"); })
      .def(
          "contract",
          [](const CtcEvalAngle& c, const Interval& t, Interval& z, Tube& x, const Tube& v) {
            return c.contract(t, z, x, v);
          },
          py::arg("t"), py::arg("z").noconvert(), py::arg("x"), py::arg("v"), nogil,
          DOC(CtcEvalAngle, contract, Interval_Interval_Tube_Tube));

  py::class_<CtcAngleEquation, Ctc, std::shared_ptr<CtcAngleEquation>>(m, "CtcAngleEquation", DOC(CtcAngleEquation))
      .def(py::init<std::vector<int>, const Function&>(), py::arg("signs"), py::arg("f"),
           DOC(CtcAngleEquation, CtcAngleEquation))
      .SILLAGE_DEFS(CtcAngleEquation, signs, function);
}

}  // namespace sillage::python
