// SVG figures and HTML index pages.
#include <pybind11/stl.h>

#include "bindings.h"
#include "sillage/figures/figure.h"
#include "sillage/figures/html.h"

namespace sillage::python {

void init_figures(py::module_& m) {
  py::class_<Style>(m, "Style", "Fill and stroke of a shape (SVG colours).")
      .def(py::init([](std::string fill, std::string stroke, double stroke_width, double opacity,
                       std::string css_class) {
             return Style{std::move(fill), std::move(stroke), stroke_width, opacity, std::move(css_class)};
           }),
           py::arg("fill") = "none", py::arg("stroke") = "black", py::arg("stroke_width") = 1.0,
           py::arg("opacity") = 1.0, py::arg("css_class") = "")
      .def_readwrite("fill", &Style::fill)
      .def_readwrite("stroke", &Style::stroke)
      .def_readwrite("stroke_width", &Style::stroke_width)
      .def_readwrite("opacity", &Style::opacity)
      .def_readwrite("css_class", &Style::css_class);
  m.def("paving_style", &paving_style, py::arg("tag"), "The thesis colours of a paving leaf.");

  py::class_<Figure>(m, "Figure", "An SVG figure in world coordinates.")
      .def(py::init<const IntervalVector&, double, double>(), py::arg("view"), py::arg("width_px") = 600.0,
           py::arg("height_px") = 0.0)
      .def("set_title", &Figure::set_title, py::arg("title"))
      .def("set_labels", &Figure::set_labels, py::arg("x_label"), py::arg("y_label"))
      .def("set_projection", &Figure::set_projection, py::arg("i"), py::arg("j"))
      .def("draw_box", &Figure::draw_box, py::arg("box"), py::arg("style") = Style{})
      .def("draw_boxes", &Figure::draw_boxes, py::arg("boxes"), py::arg("style") = Style{})
      .def("draw_ring", &Figure::draw_ring, py::arg("center"), py::arg("radius"), py::arg("style") = Style{})
      .def("draw_point", &Figure::draw_point, py::arg("p"), py::arg("radius_px") = 3.0,
           py::arg("style") = Style{"black", "none", 0, 1, ""})
      .def("draw_polyline", &Figure::draw_polyline, py::arg("points"), py::arg("style") = Style{},
           py::arg("closed") = false)
      .def("draw_paving", &Figure::draw_paving, py::arg("paving"), py::arg("show_outside") = true)
      .def("draw_contour", &Figure::draw_contour, py::arg("loops"),
           py::arg("style") = Style{"none", "black", 1.5, 1, ""})
      .def("draw_text", &Figure::draw_text, py::arg("p"), py::arg("text"), py::arg("size_px") = 12.0,
           py::arg("colour") = "black")
      .def("nb_shapes", &Figure::nb_shapes)
      .def("svg", &Figure::svg)
      .def("save", &Figure::save, py::arg("path"))
      .def("px", &Figure::px, py::arg("x"))
      .def("py", &Figure::py, py::arg("y"))
      .def("_repr_svg_", &Figure::svg);  // inline display in Jupyter

  py::class_<Html>(m, "Html", "Gathers figures into a directory with an index.html.")
      .def(py::init<std::string>(), py::arg("title"))
      .def("add", &Html::add, py::arg("figure"), py::arg("file_name"), py::arg("caption"))
      .def("add_text", &Html::add_text, py::arg("text"))
      .def("nb_figures", &Html::nb_figures)
      .def("index", &Html::index)
      .def("save", &Html::save, py::arg("directory"));
}

}  // namespace sillage::python
