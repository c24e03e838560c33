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
      .def_readwrite("fill", &Style::fill, DOC(Style, fill))
      .def_readwrite("stroke", &Style::stroke, DOC(Style, stroke))
      .def_readwrite("stroke_width", &Style::stroke_width, DOC(Style, stroke_width))
      .def_readwrite("opacity", &Style::opacity, DOC(Style, opacity))
      .def_readwrite("css_class", &Style::css_class, DOC(Style, css_class))
      .def_readwrite("label", &Style::label, DOC(Style, label))
      .def("__repr__", [](const Style& st) {
        return "Style(fill=" + quoted(st.fill) + ", stroke=" + quoted(st.stroke) + ", stroke_width=" +
               num(st.stroke_width) + ", opacity=" + num(st.opacity) + ")";
      });
  m.def("paving_style", &paving_style, py::arg("tag"), DOC(paving_style));

  py::class_<Figure>(m, "Figure", DOC(Figure))
      .def(py::init<const IntervalVector&, double, double>(), py::arg("view"), py::arg("width_px") = 600.0,
           py::arg("height_px") = 0.0,
           DOC(Figure, Figure))
      .def("set_title", &Figure::set_title, py::arg("title"), DOC(Figure, set_title))
      .def("set_note", &Figure::set_note, py::arg("note"), DOC(Figure, set_note))
      .def("set_labels", &Figure::set_labels, py::arg("x_label"), py::arg("y_label"),
           DOC(Figure, set_labels))
      .def("set_projection", &Figure::set_projection, py::arg("i"), py::arg("j"),
           DOC(Figure, set_projection))
      .def("draw_box", &Figure::draw_box, py::arg("box"), py::arg("style") = Style{}, DOC(Figure, draw_box))
      .def("draw_boxes", &Figure::draw_boxes, py::arg("boxes"), py::arg("style") = Style{},
           "Draws a list of boxes with one style.")
      .def("draw_ring", &Figure::draw_ring, py::arg("center"), py::arg("radius"), py::arg("style") = Style{},
           DOC(Figure, draw_ring))
      .def("draw_point", &Figure::draw_point, py::arg("p"), py::arg("radius_px") = 3.0,
           py::arg("style") = Style{"black", "none", 0, 1, ""}, DOC(Figure, draw_point))
      .def("draw_polyline", &Figure::draw_polyline, py::arg("points"), py::arg("style") = Style{},
           py::arg("closed") = false, DOC(Figure, draw_polyline))
      .def("draw_paving", &Figure::draw_paving, py::arg("paving"), py::arg("show_outside") = true,
           DOC(Figure, draw_paving))
      .def("draw_contour", &Figure::draw_contour, py::arg("loops"),
           py::arg("style") = Style{"none", "black", 1.5, 1, ""}, DOC(Figure, draw_contour))
      .def("draw_text", &Figure::draw_text, py::arg("p"), py::arg("text"), py::arg("size_px") = 12.0,
           py::arg("colour") = "black", DOC(Figure, draw_text))
      .def("nb_shapes", &Figure::nb_shapes, DOC(Figure, nb_shapes))
      .def("svg", &Figure::svg, DOC(Figure, svg))
      .def("save", &Figure::save, py::arg("path"), DOC(Figure, save))
      .def("px", &Figure::px, py::arg("x"), DOC(Figure, px))
      .def("py", &Figure::py, py::arg("y"), DOC(Figure, py))
      .def("_repr_svg_", &Figure::svg)  // inline display in Jupyter
      .def("__repr__", [](const Figure& f) { return "Figure(" + std::to_string(f.nb_shapes()) + " shapes)"; });

  py::class_<Html>(m, "Html", DOC(Html))
      .def(py::init<std::string>(), py::arg("title"), DOC(Html, Html))
      .def("add", &Html::add, py::arg("figure"), py::arg("file_name"), py::arg("caption"),
           DOC(Html, add))
      .def("add_text", &Html::add_text, py::arg("text"), DOC(Html, add_text))
      .def("nb_figures", &Html::nb_figures, DOC(Html, nb_figures))
      .def("index", &Html::index, DOC(Html, index))
      .def("save", &Html::save, py::arg("directory"), DOC(Html, save))
      .def("__repr__", [](const Html& h) { return "Html(" + std::to_string(h.nb_figures()) + " figures)"; });
}

}  // namespace sillage::python
