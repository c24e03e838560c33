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
      .def(py::init<>(), "The evaluation contractor, time sampling enabled.")
      .def("enable_time_sampling", &CtcEval::enable_time_sampling, py::arg("on"),
           "Allows (on=True, the default) or forbids a degenerate t that is not a time point to sample the TDomain "
           "there (a new gate in every tube on it). In a ContractorNetwork it is forbidden: the layout is fixed.")
      .def("time_sampling", &CtcEval::time_sampling, "Whether a degenerate t may sample the TDomain.")
      .def("enable_gates_at_time_bounds", &CtcEval::enable_gates_at_time_bounds, py::arg("on"),
           "In a ContractorNetwork: add the bounds of t as time points of y's TDomain at the next contract() "
           "(before the propagation), so that y at the ends of t and inside those slices is as tight as (5.6) "
           "allows. Off by default.")
      .def("gates_at_time_bounds", &CtcEval::gates_at_time_bounds,
           "Whether a network adds the bounds of t as time points.")
      .def(
          "contract",
          [](const CtcEval& c, Interval& t, Interval& z, Tube& y, const Tube* w) {
            return w ? c.contract(t, z, y, *w) : c.contract(t, z, y);
          },
          py::arg("t").noconvert(), py::arg("z").noconvert(), py::arg("y"), py::arg("w") = nullptr,
          "Contracts t, z and the tube y for z = y(t), y' = w (Prop. 5.1, (5.6)): t &= y^-1(z), z &= y(t), y &= "
          "the trajectories through z at a time of t; in place. Without w only t, z and (for a time point t) its "
          "gate are contracted. Returns False when inconsistent (Lemma 5.1: t, z and y are then set empty).")
      .def(
          "contract",
          [](const CtcEval& c, Interval& t, IntervalVector& z, TubeVector& y, const TubeVector* w) {
            return w ? c.contract(t, z, y, *w) : c.contract(t, z, y);
          },
          py::arg("t").noconvert(), py::arg("z").noconvert(), py::arg("y"), py::arg("w") = nullptr,
          "The same for a tube vector y with values z (a box): one time t for every component. Returns False when "
          "inconsistent.");

  py::class_<CtcIncrement, NetworkCtc, std::shared_ptr<CtcIncrement>>(
      m, "CtcIncrement",
      "x(t_{k+1}) - x(t_k) ∈ [i](k) for every slice k (odometry increments): contract(x, i) contracts the\n"
      "gates of x in place (Tube or TubeVector); returns False if x is empty.")
      .def(py::init<>(), "The increment contractor.")
      .def("contract", py::overload_cast<Tube&, const Tube&>(&CtcIncrement::contract, py::const_), py::arg("x"),
           py::arg("i"),
           "Contracts the gates of the tube x with x(t_{k+1}) - x(t_k) in i(k) for every slice k, in place; "
           "returns False if x is empty.")
      .def("contract", py::overload_cast<TubeVector&, const TubeVector&>(&CtcIncrement::contract, py::const_),
           py::arg("x"), py::arg("i"), "The same for a tube vector x, component by component.");
}

}  // namespace sillage::python
