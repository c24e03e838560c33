// SVG figures of tubes (thesis Figs. 3.4-3.12): the same names as in C++.
#include <pybind11/stl.h>

#include "bindings.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"

namespace sillage::python {

void init_tube_figures(py::module_& m) {
  py::class_<TubeStyle>(m, "TubeStyle", "Styles of tube figures and the aggregation tolerance merge_px.")
      .def(py::init([](bool show_gates, double merge_px) {
             TubeStyle s;
             s.show_gates = show_gates;
             s.merge_px = merge_px;
             return s;
           }),
           py::arg("show_gates") = false, py::arg("merge_px") = 1.0)
      .def_readwrite("slices", &TubeStyle::slices)
      .def_readwrite("gates", &TubeStyle::gates)
      .def_readwrite("truth", &TubeStyle::truth)
      .def_readwrite("initial", &TubeStyle::initial)
      .def_readwrite("final", &TubeStyle::final)
      .def_readwrite("show_gates", &TubeStyle::show_gates)
      .def_readwrite("merge_px", &TubeStyle::merge_px);

  py::enum_<ThicknessMeasure>(m, "ThicknessMeasure")
      .value("MaxDiameter", ThicknessMeasure::MaxDiameter)
      .value("Diagonal", ThicknessMeasure::Diagonal);

  m.def("draw_tube", &draw_tube, py::arg("fig"), py::arg("tube"), py::arg("style") = TubeStyle{},
        py::arg("truth") = py::none(),
        "Draws a scalar tube (slices aggregated below a pixel); returns the number of slice rectangles.");
  m.def("draw_tube_vector_2d", &draw_tube_vector_2d, py::arg("fig"), py::arg("tube"), py::arg("i") = 0,
        py::arg("j") = 1, py::arg("style") = TubeStyle{}, py::arg("truth_i") = py::none(),
        py::arg("truth_j") = py::none(), "Draws the projection [x_i] x [x_j] of a tube vector, slice by slice.");
  m.def("tube_figure", &tube_figure, py::arg("tube"), py::arg("title") = "", py::arg("style") = TubeStyle{},
        py::arg("truth") = py::none(), py::arg("width_px") = 600.0, py::arg("height_px") = 300.0,
        "A Figure over the tube's domain and (clipped) codomain with the tube drawn.");
  m.def("tube_vector_figure", &tube_vector_figure, py::arg("tube"), py::arg("i") = 0, py::arg("j") = 1,
        py::arg("title") = "", py::arg("style") = TubeStyle{}, py::arg("truth_i") = py::none(),
        py::arg("truth_j") = py::none(), py::arg("width_px") = 600.0);
  m.def("thickness_values", py::overload_cast<const Tube&>(&thickness_values), py::arg("tube"));
  m.def("thickness_values", py::overload_cast<const TubeVector&, ThicknessMeasure>(&thickness_values),
        py::arg("tube"), py::arg("measure") = ThicknessMeasure::MaxDiameter);
  m.def("thickness_figure", py::overload_cast<const Tube&, const std::string&, double, double>(&thickness_figure),
        py::arg("tube"), py::arg("title") = "Thickness d(t)", py::arg("width_px") = 600.0,
        py::arg("height_px") = 250.0, "The thickness d(t) as a step curve (thesis Fig. 3.12).");
  m.def("thickness_figure",
        py::overload_cast<const TubeVector&, ThicknessMeasure, const std::string&, double, double>(
            &thickness_figure),
        py::arg("tube"), py::arg("measure") = ThicknessMeasure::MaxDiameter, py::arg("title") = "Thickness d(t)",
        py::arg("width_px") = 600.0, py::arg("height_px") = 250.0);
}

}  // namespace sillage::python
