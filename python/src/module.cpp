// The _sillage extension module: one init function per library layer.
#include <pybind11/pybind11.h>

#include "bindings.h"

PYBIND11_MODULE(_sillage, m) {
  m.doc() = "sillage: guaranteed state estimation by constraint programming over intervals and tubes";
  m.attr("__version__") = SILLAGE_VERSION;  // project(sillage VERSION ...) in CMakeLists.txt
  sillage::python::init_errors(m);
  sillage::python::init_budget(m);
  sillage::python::init_threads(m);
  sillage::python::init_read_file(m);
  sillage::python::init_interval(m);
  sillage::python::init_expr(m);
  sillage::python::init_ctc(m);
  sillage::python::init_cn(m);
  sillage::python::init_tube_node(m);
  sillage::python::init_paving(m);
  sillage::python::init_trajectory(m);
  sillage::python::init_tube(m);
  sillage::python::init_tube_analysis(m);
  sillage::python::init_tube_ctc(m);
  sillage::python::init_dynamics(m);
  sillage::python::init_ctc_eval(m);
  sillage::python::init_io(m);
  sillage::python::init_loops(m);
  sillage::python::init_figures(m);
  sillage::python::init_tube_figures(m);
  sillage::python::init_loop_figures(m);
  sillage::python::init_qinter(m);
  sillage::python::init_bathymetry(m);
  sillage::python::init_ctc_heading(m);
  sillage::python::init_problem(m);
  sillage::python::init_ivp(m);
  sillage::python::init_slam(m);
  sillage::python::init_ctc_second_deriv(m);
  sillage::python::init_scalar_loops(m);
  sillage::python::init_ctc_biased_increment(m);
}
