// SVG figures and HTML index pages.
#include <pybind11/stl.h>

#include <sstream>
#include <string>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/figures/figure.h"
#include "sillage/figures/html.h"

namespace sillage::python {

namespace {
// A number as Python's repr would show a short float ("1", "0.5").
std::string num(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}
std::string quoted(const std::string& x) { return py::repr(py::str(x)).cast<std::string>(); }
}  // namespace

SILLAGE_BINDING(figures, "interval", "paving") {
  py::class_<Style>(m, "Style", DOC(Style))
      .def(py::init([](std::string fill, std::string stroke, double stroke_width, double opacity,
                       std::string css_class, std::string label) {
             return Style{std::move(fill), std::move(stroke), stroke_width, opacity, std::move(css_class),
                          std::move(label)};
           }),
           py::arg("fill") = "none", py::arg("stroke") = "black", py::arg("stroke_width") = 1.0,
           py::arg("opacity") = 1.0, py::arg("css_class") = "", py::arg("label") = "",
           "fill and stroke: SVG colours ('none' for nothing); stroke_width in pixels; opacity in [0, 1];\n"
           "css_class: an optional class attribute of the SVG elements; label: its legend entry (none if empty).")
      .SILLAGE_FIELDS(Style, fill, stroke, stroke_width, opacity, css_class, label)
      .def("__repr__", [](const Style& st) {
        return "Style(fill=" + quoted(st.fill) + ", stroke=" + quoted(st.stroke) + ", stroke_width=" +
               num(st.stroke_width) + ", opacity=" + num(st.opacity) + ")";
      });
  m.SILLAGE_FN(paving_style, py::arg("tag"));

  py::class_<Figure>(m, "Figure", DOC(Figure))
      .def(py::init<const IntervalVector&, double, double>(), py::arg("view"), py::arg("width_px") = 600.0,
           py::arg("height_px") = 0.0,
           DOC(Figure, Figure))
      .SILLAGE_DEF(Figure, set_title, py::arg("title"))
      .SILLAGE_DEF(Figure, set_note, py::arg("note"))
      .SILLAGE_DEF(Figure, set_labels, py::arg("x_label"), py::arg("y_label"))
      .SILLAGE_DEF(Figure, set_projection, py::arg("i"), py::arg("j"))
      .SILLAGE_DEF(Figure, draw_box, py::arg("box"), py::arg("style") = Style{})
      .def("draw_boxes", &Figure::draw_boxes, py::arg("boxes"), py::arg("style") = Style{},
           "Draws a list of boxes with one style.")
      .SILLAGE_DEF(Figure, draw_ring, py::arg("center"), py::arg("radius"), py::arg("style") = Style{})
      .SILLAGE_DEF(Figure, draw_point, py::arg("p"), py::arg("radius_px") = 3.0,
                   py::arg("style") = Style{"black", "none", 0, 1, ""})
      .SILLAGE_DEF(Figure, draw_polyline, py::arg("points"), py::arg("style") = Style{}, py::arg("closed") = false)
      .SILLAGE_DEF(Figure, draw_paving, py::arg("paving"), py::arg("show_outside") = true)
      .SILLAGE_DEF(Figure, draw_contour, py::arg("loops"), py::arg("style") = Style{"none", "black", 1.5, 1, ""})
      .SILLAGE_DEF(Figure, draw_text, py::arg("p"), py::arg("text"), py::arg("size_px") = 12.0,
                   py::arg("colour") = "black")
      .SILLAGE_DEFS(Figure, nb_shapes, svg)
      .SILLAGE_DEF(Figure, save, py::arg("path"))
      .SILLAGE_DEF(Figure, px, py::arg("x"))
      .SILLAGE_DEF(Figure, py, py::arg("y"))
      .def("_repr_svg_", &Figure::svg)  // inline display in Jupyter
      .def("__repr__", [](const Figure& f) { return "Figure(" + std::to_string(f.nb_shapes()) + " shapes)"; });

  py::class_<Html>(m, "Html", DOC(Html))
      .def(py::init<std::string>(), py::arg("title"), DOC(Html, Html))
      .SILLAGE_DEF(Html, add, py::arg("figure"), py::arg("file_name"), py::arg("caption"))
      .SILLAGE_DEF(Html, add_text, py::arg("text"))
      .SILLAGE_DEFS(Html, nb_figures, index)
      .SILLAGE_DEF(Html, save, py::arg("directory"))
      .def("__repr__", [](const Html& h) { return "Html(" + std::to_string(h.nb_figures()) + " figures)"; });
}

}  // namespace sillage::python
