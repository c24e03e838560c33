// SVG figures of loops (thesis Figs. 6.12-6.17): the t-plane and the map, the
// same names as in C++. Optional inputs are None by default.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "sillage/figures/loops_map_figure.h"
#include "sillage/figures/tplane_figure.h"

namespace sillage::python {

namespace {

template <class T>
const T* ptr(const std::optional<T>& x) {
  return x ? &*x : nullptr;
}

}  // namespace

void init_loop_figures(py::module_& m) {
  py::enum_<LoopStatus>(m, "LoopStatus", "What a figure shows of a detection: proven (orange), unproven (black), "
                                         "partial (grey).")
      .value("Proven", LoopStatus::Proven)
      .value("Unproven", LoopStatus::Unproven)
      .value("Partial", LoopStatus::Partial);
  m.def("loop_status", &loop_status, py::arg("loop"),
        "The status of a detection: Proven (by the degree test T), Unproven (complete, not proven) or Partial (not "
        "complete).");
  m.def("loop_style", &loop_style, py::arg("status"), "Fill and stroke of a status in the figures.");

  py::class_<TPlaneFigureOptions>(m, "TPlaneFigureOptions", "Drawing options of tplane_figure.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: min_leaf_px 2, marker_px 3, crossing_px 2, show_diagonal True.")
      .def_readwrite("min_leaf_px", &TPlaneFigureOptions::min_leaf_px,
                     "Leaves smaller than this (pixels, both sides) are covered by the outline of their component.")
      .def_readwrite("marker_px", &TPlaneFigureOptions::marker_px,
                     "Radius of the disk marker of components smaller than 2 * marker_px.")
      .def_readwrite("crossing_px", &TPlaneFigureOptions::crossing_px, "Radius of the true-crossing points.")
      .def_readwrite("show_diagonal", &TPlaneFigureOptions::show_diagonal, "Draw the diagonal t1 = t2.");
  m.def(
      "tplane_figure",
      [](const TPlane& tp, const std::optional<std::vector<PathCrossing>>& crossings, const std::string& title,
         const std::optional<IntervalVector>& view, double width_px, const TPlaneFigureOptions& options) {
        return tplane_figure(tp, ptr(crossings), title, ptr(view), width_px, options);
      },
      py::arg("tplane"), py::arg("crossings") = py::none(), py::arg("title") = "", py::arg("view") = py::none(),
      py::arg("width_px") = 600.0, py::arg("options") = TPlaneFigureOptions{},
      "The t-plane (Fig. 6.13): paving, detections by status, diagonal, true crossings; view zooms.");

  py::class_<LoopsMapOptions>(m, "LoopsMapOptions", "Drawing options of loops_map_figure.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: show_partial, boxes and projections True, path_px 0.5, crossing_px 2.5.")
      .def_readwrite("show_partial", &LoopsMapOptions::show_partial, "Draw the partial detections too.")
      .def_readwrite("boxes", &LoopsMapOptions::boxes, "Draw the map boxes.")
      .def_readwrite("projections", &LoopsMapOptions::projections,
                     "Draw the path over [t1] and [t2] (needs the path times).")
      .def_readwrite("path_px", &LoopsMapOptions::path_px,
                     "The path polyline keeps a point when it moved this far (pixels) from the last kept one.")
      .def_readwrite("crossing_px", &LoopsMapOptions::crossing_px, "Radius of the true crossing points.");
  m.def(
      "loops_map_figure",
      [](const TPlane& tp, const std::optional<std::vector<Vector>>& path,
         const std::optional<std::vector<double>>& path_times, const TubeVector* positions,
         const std::optional<std::vector<PathCrossing>>& crossings, const std::string& title, double width_px,
         const LoopsMapOptions& options) {
        return loops_map_figure(tp, ptr(path), ptr(path_times), positions, ptr(crossings), title, width_px,
                                options);
      },
      py::arg("tplane"), py::arg("path") = py::none(), py::arg("path_times") = py::none(),
      py::arg("positions") = py::none(), py::arg("crossings") = py::none(), py::arg("title") = "",
      py::arg("width_px") = 700.0, py::arg("options") = LoopsMapOptions{},
      "The map (Fig. 6.12): position tube, path (points (x, y)), detections as map boxes and, with the path "
      "times, as the path over [t1] and [t2].");
}

}  // namespace sillage::python
