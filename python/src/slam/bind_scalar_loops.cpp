// The loops of a scalar configuration (scalar_loops.h): the pieces of the loop
// set of a 1-D p and their sign-change existence test (Borda's weighing).
#include <pybind11/stl.h>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/slam/scalar_loops.h"

namespace sillage::python {

SILLAGE_BINDING(scalar_loops, "tube") {
  py::class_<ScalarLoop>(m, "ScalarLoop", DOC(ScalarLoop))
      .def(py::init<>(), "An empty piece, not proven.")
      .SILLAGE_FIELDS(ScalarLoop, boxes, hull, proven)
      .def("__repr__", [](const ScalarLoop& l) { return repr(l); }, "ScalarLoop(boxes=..., hull=..., proven=...).");
  m.SILLAGE_FN(scalar_loop_exists, py::arg("boxes"), py::arg("p"), py::arg("w"), nogil);
  m.def(
      "scalar_loops", [](double eps, const TubeVector& p, const TubeVector& w) { return scalar_loops(eps, p, w); },
      py::arg("eps"), py::arg("p"), py::arg("w"), nogil, DOC(scalar_loops));
}

}  // namespace sillage::python
