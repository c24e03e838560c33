// SVG figures of tubes (thesis Figs. 3.4-3.12): the same names as in C++.
#include <pybind11/stl.h>

#include <sstream>
#include <string>

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
           py::arg("show_gates") = false, py::arg("merge_px") = 1.0,
           "show_gates: draw the gates as segments; merge_px: slices narrower than this many pixels are\n"
           "drawn as their hull (aggregation, never hiding a value).")
      .def_readwrite("slices", &TubeStyle::slices, "Style of the slice rectangles.")
      .def_readwrite("gates", &TubeStyle::gates, "Style of the gates.")
      .def_readwrite("truth", &TubeStyle::truth, "Style of the true trajectory.")
      .def_readwrite("initial", &TubeStyle::initial, "Style of the initial gate (2-D projections).")
      .def_readwrite("final", &TubeStyle::final, "Style of the final gate (2-D projections).")
      .def_readwrite("show_gates", &TubeStyle::show_gates, "Draw the gates.")
      .def_readwrite("merge_px", &TubeStyle::merge_px, "Aggregation tolerance in pixels.")
      .def("__repr__", [](const TubeStyle& st) {
        std::ostringstream os;
        os << "TubeStyle(show_gates=" << (st.show_gates ? "True" : "False") << ", merge_px=" << st.merge_px << ")";
        return os.str();
      });

  py::enum_<ThicknessMeasure>(m, "ThicknessMeasure", "How the thickness of a tube vector's slice is measured.")
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
        "A Figure over the tube's domain (axis 't (s)') and (clipped) codomain with the tube drawn.");
  m.def("tube_vector_figure", &tube_vector_figure, py::arg("tube"), py::arg("i") = 0, py::arg("j") = 1,
        py::arg("title") = "", py::arg("style") = TubeStyle{}, py::arg("truth_i") = py::none(),
        py::arg("truth_j") = py::none(), py::arg("width_px") = 600.0,
        "A Figure of the projection [x_i] x [x_j] of a tube vector (axes x{i+1}, x{j+1}), with the tube drawn.");
  m.def("thickness_values", py::overload_cast<const Tube&>(&thickness_values), py::arg("tube"),
        "The thickness d(t) of each slice (its diameter), a list of N floats.");
  m.def("thickness_values", py::overload_cast<const TubeVector&, ThicknessMeasure>(&thickness_values),
        py::arg("tube"), py::arg("measure") = ThicknessMeasure::MaxDiameter,
        "Per slice: the max diameter over the components, or the diagonal of the slice box (Diagonal).");
  m.def("thickness_figure", py::overload_cast<const Tube&, const std::string&, double, double>(&thickness_figure),
        py::arg("tube"), py::arg("title") = "Thickness d(t)", py::arg("width_px") = 600.0,
        py::arg("height_px") = 250.0, "The thickness d(t) as a step curve (thesis Fig. 3.12); axis 't (s)'.");
  m.def("thickness_figure",
        py::overload_cast<const TubeVector&, ThicknessMeasure, const std::string&, double, double>(
            &thickness_figure),
        py::arg("tube"), py::arg("measure") = ThicknessMeasure::MaxDiameter, py::arg("title") = "Thickness d(t)",
        py::arg("width_px") = 600.0, py::arg("height_px") = 250.0,
        "The thickness d(t) of a tube vector (see thickness_values) as a step curve; axis 't (s)'.");
}

}  // namespace sillage::python
