// SVG figures of loops (thesis Figs. 6.12-6.17): the t-plane and the map, the
// same names as in C++. Optional inputs are None by default.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/figures/loops_map_figure.h"
#include "sillage/figures/tplane_figure.h"

namespace sillage::python {

namespace {

template <class T>
const T* ptr(const std::optional<T>& x) {
  return x ? &*x : nullptr;
}

}  // namespace

SILLAGE_BINDING(loop_figures, "interval", "loops", "tube") {
  py::enum_<LoopStatus>(m, "LoopStatus", DOC(LoopStatus))
      .value("Proven", LoopStatus::Proven)
      .value("Unproven", LoopStatus::Unproven)
      .value("Partial", LoopStatus::Partial);
  m.SILLAGE_FN(loop_status, py::arg("loop"));
  m.SILLAGE_FN(loop_style, py::arg("status"));

  py::class_<TPlaneFigureOptions>(m, "TPlaneFigureOptions", DOC(TPlaneFigureOptions))
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: min_leaf_px 2, marker_px 3, crossing_px 2, show_diagonal True.")
      .SILLAGE_FIELDS(TPlaneFigureOptions, min_leaf_px, marker_px, crossing_px, show_diagonal);
  m.def(
      "tplane_figure",
      [](const TPlane& tp, const std::optional<std::vector<PathCrossing>>& crossings, const std::string& title,
         const std::optional<IntervalVector>& view, double width_px, const TPlaneFigureOptions& options) {
        return tplane_figure(tp, ptr(crossings), title, ptr(view), width_px, options);
      },
      py::arg("tplane"), py::arg("crossings") = py::none(), py::arg("title") = "", py::arg("view") = py::none(),
      py::arg("width_px") = 600.0, py::arg("options") = TPlaneFigureOptions{},
      DOC(tplane_figure));

  py::class_<LoopsMapOptions>(m, "LoopsMapOptions", DOC(LoopsMapOptions))
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: show_partial, boxes and projections True, path_px 0.5, crossing_px 2.5.")
      .SILLAGE_FIELDS(LoopsMapOptions, show_partial, boxes, projections, path_px, crossing_px);
  m.def(
      "loops_map_figure",
      [](const TPlane& tp, const std::optional<std::vector<Vector>>& path,
         const std::optional<std::vector<double>>& path_times, const TubeVector* positions,
         const std::optional<std::vector<PathCrossing>>& crossings, const std::string& title, double width_px,
         const LoopsMapOptions& options, const std::string& x_label, const std::string& y_label) {
        return loops_map_figure(tp, ptr(path), ptr(path_times), positions, ptr(crossings), title, width_px,
                                options, x_label, y_label);
      },
      py::arg("tplane"), py::arg("path") = py::none(), py::arg("path_times") = py::none(),
      py::arg("positions") = py::none(), py::arg("crossings") = py::none(), py::arg("title") = "",
      py::arg("width_px") = 700.0, py::arg("options") = LoopsMapOptions{}, py::arg("x_label") = "x (m)",
      py::arg("y_label") = "y (m)",
      DOC(loops_map_figure,
          TPlane_vector_Vector_vector_double_TubeVector_vector_PathCrossing_string_double_LoopsMapOptions_string_string));
}

}  // namespace sillage::python
