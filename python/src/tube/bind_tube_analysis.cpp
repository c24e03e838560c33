// Integrals of tubes (3.7)-(3.9), the primitive tube, and TubeAnalysis (the
// synthesis tree kept for repeated O(log N) queries). The methods
// Tube.integral / Tube.partial_integral / Tube.primitive are added to the
// Tube class registered by init_tube (module.cpp calls init_tube first); each
// call uses the tube's cached synthesis tree (rebuilt after a modification).
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "arg_checks.h"
#include "bindings.h"
#include "docstrings.h"
#include "sillage/error.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/tube_integral.h"
#include "sillage/tube/tube_taylor.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::python {

namespace {

const char* const kIntegralDoc =
    "integral(t) = ∫_{t0}^{t} x (t a float or an Interval: the hull over t);\n"
    "integral(t1, t2) = the hull of ∫_{t1}^{t2} x over t1 ∈ [t1], t2 ∈ [t2] (3.9).\n"
    "Guaranteed (outward rounding). Empty tube -> empty; t outside the domain -> sillage.Error.";
const char* const kPartialDoc =
    "partial_integral(t1, t2) -> (range of ∫_{t1}^{t2} x^-, range of ∫_{t1}^{t2} x^+) over t1 ∈ [t1],\n"
    "t2 ∈ [t2]: the lower- and upper-bound integrals of (3.9).";
const char* const kPrimitiveDoc =
    "primitive(x0=0) -> Tube p with p(t0) = x0 and p' ∈ this tube: gates p(t_{k+1}) = p(t_k) + δ_k [x](k),\n"
    "slices p(t_k) + [0, δ_k]·[x](k).";

// Adds `f` as a method `name` of the Python class `cls`.
void add_method(py::object& cls, const char* name, py::cpp_function f) { py::setattr(cls, name, f); }

}  // namespace

SILLAGE_BINDING(tube_analysis, "interval", "tube") {
  py::class_<TubeAnalysis>(m, "TubeAnalysis",
                           DOC(TubeAnalysis))
      .def(py::init<const Tube&>(), py::arg("x"), py::keep_alive<1, 2>(), DOC(TubeAnalysis, TubeAnalysis))
      .SILLAGE_DEF(TubeAnalysis, eval, py::arg("t"))
      .def(
          "integral",
          [](const TubeAnalysis& a, const py::object& t1, const py::object& t2) {
            const char* where = "TubeAnalysis.integral";
            const Interval i1 = interval_arg(t1, where, "t1");
            return t2.is_none() ? a.integral(i1) : a.integral(i1, interval_arg(t2, where, "t2"));
          },
          py::arg("t1"), py::arg("t2") = py::none(), kIntegralDoc)
      .def(
          "partial_integral",
          [](const TubeAnalysis& a, const py::object& t1, const py::object& t2) {
            const char* where = "TubeAnalysis.partial_integral";
            return a.partial_integral(interval_arg(t1, where, "t1"), interval_arg(t2, where, "t2"));
          },
          py::arg("t1"), py::arg("t2"), kPartialDoc)
      .def("nb_slices", [](const TubeAnalysis& a) { return a.tree()->nb_slices(); }, "N, the tube's slice count.")
      .def("__repr__", [](const py::object& self) {
        return "TubeAnalysis(" + py::repr(py::cast(self.cast<const TubeAnalysis&>().tube())).cast<std::string>() + ")";
      });

  // Primitives from Taylor increments (tube_taylor.h).
  m.def("taylor_increments", &taylor_increments, py::arg("w"), py::arg("dw"), py::arg("noise") = Interval(0.0),
        "Enclosures of ∫ over each slice of w + e, w' ∈ dw, e(t) ∈ noise, by first-order Taylor forms from\n"
        "both gates of w (a list of N Intervals).");
  m.SILLAGE_FN(primitive_from_increments, py::arg("x"), py::arg("increments"), py::arg("x0"),
               py::arg("gates") = std::vector<Interval>());
  m.SILLAGE_FN(primitive_taylor, py::arg("w"), py::arg("dw"), py::arg("x0") = Interval(0.0),
               py::arg("noise") = Interval(0.0));

  py::object cls = m.attr("Tube");
  add_method(cls, "integral",
             py::cpp_function(
                 [](const Tube& x, const py::object& t1, const py::object& t2) {
                   const Interval i1 = interval_arg(t1, "Tube.integral", "t1");
                   return t2.is_none() ? integral(x, i1) : integral(x, i1, interval_arg(t2, "Tube.integral", "t2"));
                 },
                 py::name("integral"), py::is_method(cls), py::arg("t1"), py::arg("t2") = py::none(),
                 kIntegralDoc));
  add_method(cls, "partial_integral",
             py::cpp_function(
                 [](const Tube& x, const py::object& t1, const py::object& t2) {
                   return partial_integral(x, interval_arg(t1, "Tube.partial_integral", "t1"),
                                           interval_arg(t2, "Tube.partial_integral", "t2"));
                 },
                              py::name("partial_integral"), py::is_method(cls), py::arg("t1"), py::arg("t2"),
                              kPartialDoc));
  add_method(cls, "primitive",
             py::cpp_function([](const Tube& x, const Interval& x0) { return primitive(x, x0); },
                              py::name("primitive"), py::is_method(cls), py::arg("x0") = Interval(0.0),
                              kPrimitiveDoc));

  // The same for TubeVector, component by component (IntervalVector results).
  py::object vcls = m.attr("TubeVector");
  add_method(vcls, "integral",
             py::cpp_function(
                 [](const TubeVector& x, const py::object& t1, const py::object& t2) {
                   const Interval i1 = interval_arg(t1, "TubeVector.integral", "t1");
                   const bool two = !t2.is_none();
                   const Interval i2 = two ? interval_arg(t2, "TubeVector.integral", "t2") : Interval();
                   IntervalVector r(x.size());
                   for (std::size_t i = 0; i < x.size(); ++i) r[i] = two ? integral(x[i], i1, i2) : integral(x[i], i1);
                   return r;
                 },
                 py::name("integral"), py::is_method(vcls), py::arg("t1"), py::arg("t2") = py::none(),
                 "Tube.integral component by component, as an IntervalVector:\n"
                 "integral(t) = ∫_{t0}^{t} x, integral(t1, t2) = ∫_{t1}^{t2} x\n"
                 "(floats or Intervals, (3.7)-(3.9))."));
  add_method(vcls, "primitive",
             py::cpp_function(
                 [](const TubeVector& x, const py::object& x0) {
                   IntervalVector v0(x.size(), Interval(0.0));
                   if (!x0.is_none()) {
                     v0 = py::module_::import("sillage._sillage").attr("IntervalVector")(x0).cast<IntervalVector>();
                   }
                   if (v0.size() != x.size()) {
                     throw DimensionError("TubeVector.primitive: x0 has size " + std::to_string(v0.size()) +
                                          ", the tube vector " + std::to_string(x.size()));
                   }
                   std::vector<Tube> ps;
                   for (std::size_t i = 0; i < x.size(); ++i) ps.push_back(primitive(x[i], v0[i]));
                   return TubeVector(std::move(ps));
                 },
                 py::name("primitive"), py::is_method(vcls), py::arg("x0") = py::none(),
                 "primitive(x0=zeros) -> TubeVector p with p(t0) = x0 (a box or a list) and p' in this tube:\n"
                 "Tube.primitive component by component."));
}

}  // namespace sillage::python
