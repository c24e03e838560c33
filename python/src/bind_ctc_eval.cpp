// CtcEval (thesis Prop. 5.1): contract(t, z, y, w) on the caller's own
// Interval / IntervalVector / Tube / TubeVector objects, in place; a
// NetworkCtc, so ContractorNetwork.add(CtcEval(), [t, z, y, w]) binds it.
#include "bindings.h"
#include "sillage/dynamics/ctc_eval.h"

namespace sillage::python {

void init_ctc_eval(py::module_& m) {
  py::class_<CtcEval, NetworkCtc, std::shared_ptr<CtcEval>>(
      m, "CtcEval",
      "The evaluation contractor of z = y(t), y' = w with an uncertain t (thesis Prop. 5.1, (5.6)).\n"
      "contract(t, z, y, w) contracts t, z and y in place (w optional); returns False when inconsistent\n"
      "(then t, z and y are set empty). A degenerate t samples the TDomain unless disabled.")
      .def(py::init<>())
      .def("enable_time_sampling", &CtcEval::enable_time_sampling, py::arg("on"))
      .def("time_sampling", &CtcEval::time_sampling)
      .def(
          "contract",
          [](const CtcEval& c, Interval& t, Interval& z, Tube& y, const Tube* w) {
            return w ? c.contract(t, z, y, *w) : c.contract(t, z, y);
          },
          py::arg("t"), py::arg("z"), py::arg("y"), py::arg("w") = nullptr)
      .def(
          "contract",
          [](const CtcEval& c, Interval& t, IntervalVector& z, TubeVector& y, const TubeVector* w) {
            return w ? c.contract(t, z, y, *w) : c.contract(t, z, y);
          },
          py::arg("t"), py::arg("z"), py::arg("y"), py::arg("w") = nullptr);
}

}  // namespace sillage::python
