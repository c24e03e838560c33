#pragma once
// One function per library layer registers its classes in the module;
// each lives in bind_<layer>.cpp.
#include <pybind11/pybind11.h>

#include <string>

namespace sillage {
class Interval;
}

namespace sillage::python {
namespace py = pybind11;

// A Python int (any size; numpy integers too) as the tightest interval:
// itself when it is a double, else the two doubles around it (bind_interval.cpp).
bool is_int(const py::handle& h);
Interval int_enclosure(const py::handle& h);

// True when h is a numpy array. numpy is optional: while it is not imported,
// no object can be an array, and asking pybind11 would import it (and fail
// where it is not installed).
bool is_ndarray(const py::handle& h);

// copy(), __copy__ and __deepcopy__ of a value type: a C++ copy.
template <class Class>
void def_copy(Class& cls) {
  using T = typename Class::type;
  cls.def("copy", [](const T& x) { return T(x); }, "An independent copy (copy.copy and copy.deepcopy give the same).")
      .def("__copy__", [](const T& x) { return T(x); })
      .def("__deepcopy__", [](const T& x, py::dict) { return T(x); });
}
// A __repr__ "Name(field=value, ...)" over the class's properties (its
// def_readwrite / def_readonly fields), for option and result structs.
std::string fields_repr(const py::object& self);

void init_errors(py::module_& m);
void init_budget(py::module_& m);
void init_threads(py::module_& m);
void init_read_file(py::module_& m);
void init_interval(py::module_& m);
void init_expr(py::module_& m);
void init_ctc(py::module_& m);
void init_cn(py::module_& m);
void init_tube_node(py::module_& m);
void init_paving(py::module_& m);
void init_trajectory(py::module_& m);
void init_tdomain(py::module_& m);  // called by init_tube, first
void init_tube(py::module_& m);
void init_tube_analysis(py::module_& m);
void init_tube_ctc(py::module_& m);
void init_dynamics(py::module_& m);
void init_ctc_eval(py::module_& m);
void init_io(py::module_& m);
void init_loops(py::module_& m);
void init_tube_figures(py::module_& m);
void init_figures(py::module_& m);
void init_loop_figures(py::module_& m);
void init_problem(py::module_& m);
void init_qinter(py::module_& m);
void init_bathymetry(py::module_& m);
void init_ctc_heading(py::module_& m);
void init_ivp(py::module_& m);
void init_slam(py::module_& m);
void init_ctc_second_deriv(py::module_& m);
void init_scalar_loops(py::module_& m);
void init_ctc_biased_increment(py::module_& m);
}  // namespace sillage::python
