// SVG figures and HTML index pages.
#include <pybind11/stl.h>

#include <sstream>
#include <string>

#include "bindings.h"
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

void init_figures(py::module_& m) {
  py::class_<Style>(m, "Style", "Fill and stroke of a shape (SVG colours).")
      .def(py::init([](std::string fill, std::string stroke, double stroke_width, double opacity,
                       std::string css_class) {
             return Style{std::move(fill), std::move(stroke), stroke_width, opacity, std::move(css_class)};
           }),
           py::arg("fill") = "none", py::arg("stroke") = "black", py::arg("stroke_width") = 1.0,
           py::arg("opacity") = 1.0, py::arg("css_class") = "",
           "fill and stroke: SVG colours ('none' for nothing); stroke_width in pixels; opacity in [0, 1];\n"
           "css_class: an optional class attribute of the SVG elements.")
      .def_readwrite("fill", &Style::fill, "SVG fill colour.")
      .def_readwrite("stroke", &Style::stroke, "SVG stroke colour.")
      .def_readwrite("stroke_width", &Style::stroke_width, "Stroke width in pixels.")
      .def_readwrite("opacity", &Style::opacity, "Opacity in [0, 1].")
      .def_readwrite("css_class", &Style::css_class, "Class attribute of the SVG elements ('' for none).")
      .def("__repr__", [](const Style& st) {
        return "Style(fill=" + quoted(st.fill) + ", stroke=" + quoted(st.stroke) + ", stroke_width=" +
               num(st.stroke_width) + ", opacity=" + num(st.opacity) + ")";
      });
  m.def("paving_style", &paving_style, py::arg("tag"), "The thesis colours of a paving leaf.");

  py::class_<Figure>(m, "Figure", "An SVG figure in world coordinates.")
      .def(py::init<const IntervalVector&, double, double>(), py::arg("view"), py::arg("width_px") = 600.0,
           py::arg("height_px") = 0.0,
           "view: the bounded 2-D window shown (non-zero widths); width_px: the plot width; height_px = 0\n"
           "keeps the aspect ratio of the view.")
      .def("set_title", &Figure::set_title, py::arg("title"), "The title above the plot.")
      .def("set_labels", &Figure::set_labels, py::arg("x_label"), py::arg("y_label"),
           "Axis labels, units included (e.g. 't (s)', 'x (m)').")
      .def("set_projection", &Figure::set_projection, py::arg("i"), py::arg("j"),
           "Dimensions of the drawn boxes shown on the x and y axes (default 0, 1).")
      .def("draw_box", &Figure::draw_box, py::arg("box"), py::arg("style") = Style{}, "Draws one box.")
      .def("draw_boxes", &Figure::draw_boxes, py::arg("boxes"), py::arg("style") = Style{},
           "Draws a list of boxes with one style.")
      .def("draw_ring", &Figure::draw_ring, py::arg("center"), py::arg("radius"), py::arg("style") = Style{},
           "The annulus {p : |p - center| in radius} (a disk when radius.lb() <= 0).")
      .def("draw_point", &Figure::draw_point, py::arg("p"), py::arg("radius_px") = 3.0,
           py::arg("style") = Style{"black", "none", 0, 1, ""}, "A dot of radius_px pixels at p.")
      .def("draw_polyline", &Figure::draw_polyline, py::arg("points"), py::arg("style") = Style{},
           py::arg("closed") = false, "A polyline through the points (a polygon if closed).")
      .def("draw_paving", &Figure::draw_paving, py::arg("paving"), py::arg("show_outside") = true,
           "Every leaf of the paving in the thesis colours (Outside leaves if show_outside).")
      .def("draw_contour", &Figure::draw_contour, py::arg("loops"),
           py::arg("style") = Style{"none", "black", 1.5, 1, ""}, "Oriented contour loops as polygons.")
      .def("draw_text", &Figure::draw_text, py::arg("p"), py::arg("text"), py::arg("size_px") = 12.0,
           py::arg("colour") = "black", "Text at the point p (world coordinates).")
      .def("nb_shapes", &Figure::nb_shapes, "Number of SVG elements drawn so far.")
      .def("svg", &Figure::svg, "The SVG document as a string.")
      .def("save", &Figure::save, py::arg("path"), "Writes svg() to a file (sillage.Error if it cannot).")
      .def("px", &Figure::px, py::arg("x"), "World x -> pixel x of the SVG.")
      .def("py", &Figure::py, py::arg("y"), "World y -> pixel y of the SVG.")
      .def("_repr_svg_", &Figure::svg)  // inline display in Jupyter
      .def("__repr__", [](const Figure& f) { return "Figure(" + std::to_string(f.nb_shapes()) + " shapes)"; });

  py::class_<Html>(m, "Html", "Gathers figures into a directory with an index.html.")
      .def(py::init<std::string>(), py::arg("title"), "An empty page with this title.")
      .def("add", &Html::add, py::arg("figure"), py::arg("file_name"), py::arg("caption"),
           "Adds the figure (copied now) as file_name, a plain unique name ending in '.svg'.")
      .def("add_text", &Html::add_text, py::arg("text"), "Adds a paragraph between figures.")
      .def("nb_figures", &Html::nb_figures, "Number of figures added.")
      .def("index", &Html::index, "The index page alone, as a string.")
      .def("save", &Html::save, py::arg("directory"), "Writes the SVG files and index.html (directory created).")
      .def("__repr__", [](const Html& h) { return "Html(" + std::to_string(h.nb_figures()) + " figures)"; });
}

}  // namespace sillage::python
