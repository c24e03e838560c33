// CtcEval (thesis Prop. 5.1) and CtcIncrement (odometry increments): contract(t, z, y, w) on the caller's own
// Interval / IntervalVector / Tube / TubeVector objects, in place; a
// NetworkCtc, so ContractorNetwork.add(CtcEval(), [t, z, y, w]) binds it.
#include "bindings.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_increment.h"

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
          py::arg("t").noconvert(), py::arg("z").noconvert(), py::arg("y"), py::arg("w") = nullptr)
      .def(
          "contract",
          [](const CtcEval& c, Interval& t, IntervalVector& z, TubeVector& y, const TubeVector* w) {
            return w ? c.contract(t, z, y, *w) : c.contract(t, z, y);
          },
          py::arg("t").noconvert(), py::arg("z").noconvert(), py::arg("y"), py::arg("w") = nullptr);

  py::class_<CtcIncrement, NetworkCtc, std::shared_ptr<CtcIncrement>>(
      m, "CtcIncrement",
      "x(t_{k+1}) - x(t_k) ∈ [i](k) for every slice k (odometry increments): contract(x, i) contracts the\n"
      "gates of x in place (Tube or TubeVector); returns False if x is empty.")
      .def(py::init<>())
      .def("contract", py::overload_cast<Tube&, const Tube&>(&CtcIncrement::contract, py::const_), py::arg("x"),
           py::arg("i"))
      .def("contract", py::overload_cast<TubeVector&, const TubeVector&>(&CtcIncrement::contract, py::const_),
           py::arg("x"), py::arg("i"));
}

}  // namespace sillage::python
