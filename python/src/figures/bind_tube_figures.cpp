// SVG figures of tubes (thesis Figs. 3.4-3.12): the same names as in C++.
#include <pybind11/stl.h>

#include <optional>
#include <sstream>
#include <string>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/figures/map_envelope.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"

namespace sillage::python {

SILLAGE_BINDING(tube_figures, "trajectory", "tube") {
  py::class_<TubeStyle>(m, "TubeStyle", DOC(TubeStyle))
      .def(py::init([](bool show_gates, double merge_px) {
             TubeStyle s;
             s.show_gates = show_gates;
             s.merge_px = merge_px;
             return s;
           }),
           py::arg("show_gates") = false, py::arg("merge_px") = 1.0,
           "show_gates: draw the gates as segments; merge_px: slices narrower than this many pixels are\n"
           "drawn as their hull (aggregation, never hiding a value).")
      .SILLAGE_FIELDS(TubeStyle, slices, gates, truth, initial)
      .def_readwrite("final", &TubeStyle::final, "Style of the final gate (2-D projections).")
      .SILLAGE_FIELDS(TubeStyle, show_gates, merge_px, landmarks, landmark_px, min_px)
      .def("__repr__", [](const TubeStyle& st) {
        std::ostringstream os;
        os << "TubeStyle(show_gates=" << (st.show_gates ? "True" : "False") << ", merge_px=" << st.merge_px << ")";
        return os.str();
      });

  py::enum_<ThicknessMeasure>(m, "ThicknessMeasure", DOC(ThicknessMeasure))
      .value("MaxDiameter", ThicknessMeasure::MaxDiameter)
      .value("Diagonal", ThicknessMeasure::Diagonal);

  m.SILLAGE_FN(draw_tube, py::arg("fig"), py::arg("tube"), py::arg("style") = TubeStyle{},
               py::arg("truth") = py::none());
  m.SILLAGE_FN(draw_tube_vector_2d, py::arg("fig"), py::arg("tube"), py::arg("i") = 0, py::arg("j") = 1,
               py::arg("style") = TubeStyle{}, py::arg("truth_i") = py::none(), py::arg("truth_j") = py::none());
  m.SILLAGE_FN(tube_figure, py::arg("tube"), py::arg("title") = "", py::arg("style") = TubeStyle{},
               py::arg("truth") = py::none(), py::arg("width_px") = 600.0, py::arg("height_px") = 300.0,
               py::arg("name") = "x");
  // Landmarks as an optional list: None (no landmark) maps to a null pointer.
  m.def(
      "tube_vector_figure",
      [](const TubeVector& x, std::size_t i, std::size_t j, const std::string& title, const TubeStyle& style,
         const Trajectory* truth_i, const Trajectory* truth_j, double width_px,
         const std::optional<std::vector<Vector>>& landmarks, const std::string& name_i, const std::string& name_j) {
        return tube_vector_figure(x, i, j, title, style, truth_i, truth_j, width_px,
                                  landmarks ? &*landmarks : nullptr, name_i, name_j);
      },
      py::arg("tube"), py::arg("i") = 0, py::arg("j") = 1, py::arg("title") = "", py::arg("style") = TubeStyle{},
      py::arg("truth_i") = py::none(), py::arg("truth_j") = py::none(), py::arg("width_px") = 600.0,
      py::arg("landmarks") = py::none(), py::arg("name_i") = "", py::arg("name_j") = "", DOC(tube_vector_figure));
  m.def(
      "map_envelope_figure",
      [](const TubeVector& x, std::size_t i, std::size_t j, const std::string& title, const TubeStyle& style,
         const Trajectory* truth_i, const Trajectory* truth_j, double width_px,
         const std::optional<std::vector<Vector>>& landmarks, const std::string& name_i, const std::string& name_j,
         std::size_t boxes) {
        return map_envelope_figure(x, i, j, title, style, truth_i, truth_j, width_px,
                                   landmarks ? &*landmarks : nullptr, name_i, name_j, boxes);
      },
      py::arg("tube"), py::arg("i") = 0, py::arg("j") = 1, py::arg("title") = "", py::arg("style") = TubeStyle{},
      py::arg("truth_i") = py::none(), py::arg("truth_j") = py::none(), py::arg("width_px") = 600.0,
      py::arg("landmarks") = py::none(), py::arg("name_i") = "", py::arg("name_j") = "", py::arg("boxes") = 8,
      DOC(map_envelope_figure));
  m.def("map_envelope", &map_envelope, py::arg("tube"), py::arg("i"), py::arg("j"), py::arg("window"),
        py::arg("cells") = 300, DOC(map_envelope));
  m.def("thickness_values", py::overload_cast<const Tube&>(&thickness_values), py::arg("tube"),
        DOC(thickness_values, Tube));
  m.def("thickness_values", py::overload_cast<const TubeVector&, ThicknessMeasure>(&thickness_values),
        py::arg("tube"), py::arg("measure") = ThicknessMeasure::MaxDiameter,
        DOC(thickness_values, TubeVector_ThicknessMeasure));
  m.def("thickness_figure", py::overload_cast<const Tube&, const std::string&, double, double>(&thickness_figure),
        py::arg("tube"), py::arg("title") = "Thickness d(t)", py::arg("width_px") = 600.0,
        py::arg("height_px") = 250.0, DOC(thickness_figure, Tube_string_double_double));
  m.def("thickness_figure",
        py::overload_cast<const TubeVector&, ThicknessMeasure, const std::string&, double, double>(
            &thickness_figure),
        py::arg("tube"), py::arg("measure") = ThicknessMeasure::MaxDiameter, py::arg("title") = "Thickness d(t)",
        py::arg("width_px") = 600.0, py::arg("height_px") = 250.0,
        DOC(thickness_figure, TubeVector_ThicknessMeasure_string_double_double));
}

}  // namespace sillage::python
