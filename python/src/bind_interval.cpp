#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "sillage/interval/interval.h"

namespace sillage::python {
void init_interval(py::module_& m) {
  py::class_<Interval>(m, "Interval")
      .def(py::init<>())
      .def(py::init<double>())
      .def(py::init<double, double>())
      .def_static("empty", &Interval::empty)
      .def_static("all_reals", &Interval::all_reals)
      .def("lb", &Interval::lb)
      .def("ub", &Interval::ub)
      .def("mid", &Interval::mid)
      .def("diam", &Interval::diam)
      .def("rad", &Interval::rad)
      .def("is_empty", &Interval::is_empty)
      .def("contains", &Interval::contains)
      .def("is_subset", &Interval::is_subset)
      .def(py::self + py::self)
      .def(py::self - py::self)
      .def(py::self * py::self)
      .def(py::self / py::self)
      .def(py::self & py::self)
      .def(py::self | py::self)
      .def(py::self == py::self)
      .def("__repr__", &Interval::str);
}
}  // namespace sillage::python
