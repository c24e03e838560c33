// The slam/ layer (thesis ch. 7): CtcT1T2 (Alg. 11), CtcOmega (Alg. 12).
// Contractions run with the GIL released.
#include <pybind11/stl.h>

#include "bindings.h"
#include "sillage/slam/ctc_omega.h"
#include "sillage/slam/ctc_t1t2.h"

namespace sillage::python {

void init_slam(py::module_& m) {
  py::class_<CtcT1T2>(m, "CtcT1T2",
                      "The inter-temporal contractor C_{t1,t2} (thesis Alg. 11, (7.23)-(7.24)): p(t1) = p(t2),\n"
                      "p' = w. contract(t1, t2, p, w) contracts the Intervals t1, t2 and the tube p in place.")
      .def(py::init<double, std::size_t>(), py::arg("ratio") = 1e-3, py::arg("max_passes") = 100,
           "The contractor; the loop of the two evaluations stops when t1, t2, p(t1) and p(t2) shrink by no more "
           "than `ratio` (0: any change), or after max_passes passes.")
      .def_property_readonly("ratio", &CtcT1T2::ratio, "The fixed-point ratio.")
      .def_property_readonly("max_passes", &CtcT1T2::max_passes, "The cap on the passes.")
      .def(
          "contract",
          [](const CtcT1T2& c, Interval& t1, Interval& t2, TubeVector& p, const TubeVector& w) {
            py::gil_scoped_release unlocked;
            return c.contract(t1, t2, p, w);
          },
          py::arg("t1").noconvert(), py::arg("t2").noconvert(), py::arg("p"), py::arg("w"),
          "Contracts t1, t2 (Intervals) and the TubeVector p in place for p(t1) = p(t2), p' = w (w a TubeVector "
          "on p's TDomain). Returns False when inconsistent (t1, t2 and p are then set empty).")
      .def(
          "contract",
          [](const CtcT1T2& c, Interval& t1, Interval& t2, Tube& p, const Tube& w) {
            py::gil_scoped_release unlocked;
            return c.contract(t1, t2, p, w);
          },
          py::arg("t1").noconvert(), py::arg("t2").noconvert(), py::arg("p"), py::arg("w"),
          "The same for a scalar Tube p with derivative w.")
      .def("__repr__", [](const CtcT1T2& c) {
        return "CtcT1T2(ratio=" + py::repr(py::float_(c.ratio())).cast<std::string>() + ", max_passes=" + std::to_string(c.max_passes()) + ")";
      });

  py::class_<CtcOmega>(m, "CtcOmega",
                       "The contractor C_Ω (thesis Alg. 12, (7.22)): p &= the hull over the t-boxes of a component\n"
                       "Ω of C_{t1,t2} on each box, computed in place without one tube copy per box.")
      .def(py::init([](const CtcT1T2& c) { return CtcOmega(c); }), py::arg("t1t2") = CtcT1T2(),
           "The contractor, with the CtcT1T2 used on each box.")
      .def(
          "contract",
          [](const CtcOmega& c, const std::vector<IntervalVector>& boxes, TubeVector& p, const TubeVector& w) {
            py::gil_scoped_release unlocked;
            return c.contract(boxes, p, w);
          },
          py::arg("boxes"), py::arg("p"), py::arg("w"),
          "Contracts the TubeVector p in place: p &= union over the t-boxes ([t1], [t2]) of CtcT1T2 on each. Boxes "
          "whose contraction is inconsistent are left out; if all are, p is emptied. Returns False if p is empty.")
      .def("__repr__", [](const CtcOmega&) { return std::string("<CtcOmega>"); });
}

}  // namespace sillage::python
