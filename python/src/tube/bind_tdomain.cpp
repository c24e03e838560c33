// Python bindings of TDomain: the time points shared by the tubes of a
// problem (slices, sampling, pickling).
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "arg_checks.h"
#include "bindings.h"
#include "docstrings.h"
#include "sillage/tube/tdomain.h"

namespace sillage::python {

SILLAGE_BINDING(tdomain, "interval") {
  py::class_<TDomain, std::shared_ptr<TDomain>>(m, "TDomain",
                          DOC(TDomain))
      .def(py::init<double, double, double>(), py::arg("t0"), py::arg("tf"), py::arg("dt"),
           DOC(TDomain, TDomain, double_double_double))
      .def(py::init<std::vector<double>>(), py::arg("times"), DOC(TDomain, TDomain, vector_double))
      .def("nb_slices", &TDomain::nb_slices, DOC(TDomain, nb_slices))
      .def("t", [](const TDomain& td, py::ssize_t k) { return td.t(index_arg(k, "TDomain.t", "index")); }, py::arg("k"),
           DOC(TDomain, t))
      .def("t0_tf", &TDomain::t0_tf, DOC(TDomain, t0_tf))
      .def("times", [](const TDomain& td) { return std::vector<double>(td.times().begin(), td.times().end()); },
           "The N+1 time points as a list of floats.")
      .def("slice_index", &TDomain::slice_index, py::arg("t"),
           DOC(TDomain, slice_index))
      .def("slice_domain",
           [](const TDomain& td, py::ssize_t k) { return td.slice_domain(index_arg(k, "TDomain.slice_domain", "slice")); },
           py::arg("k"), DOC(TDomain, slice_domain))
      .def("slice_width",
           [](const TDomain& td, py::ssize_t k) { return td.slice_width(index_arg(k, "TDomain.slice_width", "slice")); },
           py::arg("k"), DOC(TDomain, slice_width))
      .def("is_time_point", &TDomain::is_time_point, py::arg("t"), DOC(TDomain, is_time_point))
      .def("time_index", &TDomain::time_index, py::arg("t"), DOC(TDomain, time_index))
      .def("sample", py::overload_cast<double>(&TDomain::sample), py::arg("t"),
           DOC(TDomain, sample, double))
      .def("sample", py::overload_cast<const Interval&>(&TDomain::sample), py::arg("t"),
           DOC(TDomain, sample, Interval))
      .SILLAGE_DEF(TDomain, extend, py::arg("t"))
      .SILLAGE_DEF(TDomain, forget_before, py::arg("t"))
      .SILLAGE_DEF(TDomain, nb_forgotten)
      .def("nb_attached", &TDomain::nb_attached, DOC(TDomain, nb_attached))
      .def("__repr__",
           [](const TDomain& td) {
             return "TDomain(t=" + td.t0_tf().str() + ", " + std::to_string(td.nb_slices()) + " slices)";
           })
      // Pickled as its time points; tubes pickled together keep sharing one TDomain (pickle's memo).
      .def(py::pickle(
          [](const TDomain& td) { return py::make_tuple(std::vector<double>(td.times().begin(), td.times().end())); },
          [](const py::tuple& st) { return TDomain::create(st[0].cast<std::vector<double>>()); }));
}

}  // namespace sillage::python
