// CtcHeading (the displacement over each slice from the distance travelled and
// the heading, both ways): contract(p, psi, d, w) on the caller's own tubes, in
// place; a NetworkCtc, so ContractorNetwork.add(CtcHeading(track), [p, psi, d, w])
// binds it. CtcHeadingWindow, the same over windows of slices against the
// heading increments: ContractorNetwork.add(CtcHeadingWindow(...), [p, psi, d, dpsi, w]).
#include <cmath>
#include <cstddef>
#include <string>

#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"

namespace sillage::python {

SILLAGE_BINDING(ctc_heading, "cn", "tube") {
  py::class_<CtcHeading, NetworkCtc, std::shared_ptr<CtcHeading>>(m, "CtcHeading", R"doc(
p(t_{k+1}) - p(t_k) = integral over slice k of s (cos, sin)(psi + e), with d_k the
distance (slice k of the tube d, s >= 0), |e| <= track (direction of travel vs
heading) and psi' in w. Both ways: the positions p (a 2-d TubeVector) from the
heading psi, and the heading (slices and gates) from the positions, when the
displacement box excludes 0 and the heading spans less than a half turn over
the slice. Outward rounded. ContractorNetwork.add(CtcHeading(track), [p, psi, d, w]).)doc")
      .def(py::init<double>(), py::arg("track") = 0.0, DOC(CtcHeading, CtcHeading))
      .SILLAGE_DEF(CtcHeading, track)
      .def("__repr__",
           [](const CtcHeading& c) { return "CtcHeading(track=" + std::string(py::repr(py::float_(c.track()))) + ")"; })
      .def("contract",
           py::overload_cast<TubeVector&, Tube&, const Tube&, const Tube&>(&CtcHeading::contract, py::const_),
           py::arg("p"), py::arg("psi"), py::arg("d"), py::arg("w"), nogil,
           DOC(CtcHeading, contract, TubeVector_Tube_Tube_Tube))
      .def(
          "contract_local",
          [](const CtcHeading& c, Tube& px, Tube& py, Tube& psi, const Tube& d, const Tube& w, std::size_t first,
             std::size_t last) {
            std::vector<std::size_t> cx, cy, cpsi;
            bool ok = true;
            {
              py::gil_scoped_release unlocked;
              ok = c.contract_local(px, py, psi, d, w, first, last, TubeChanges(cx, 0, 0.0), TubeChanges(cy, 0, 0.0),
                                    TubeChanges(cpsi, 0, 0.0));
            }
            return py::make_tuple(ok, cx, cy, cpsi);
          },
          // Python: returns (ok, px_changed, py_changed, psi_changed), the atoms that shrank (2k: gate k, 2k+1: slice k).
          py::arg("px"), py::arg("py"), py::arg("psi"), py::arg("d"), py::arg("w"), py::arg("first"), py::arg("last"),
          DOC(CtcHeading, contract_local));

  py::class_<CtcHeadingWindow, NetworkCtc, std::shared_ptr<CtcHeadingWindow>>(m, "CtcHeadingWindow", R"doc(
p(t_b) - p(t_a) = integral over [t_a, t_b] of s (cos, sin)(psi + e), over windows of
consecutive slices (t_b - t_a >= window, one window every `stride` slices), against the
heading at the window's middle gate t_c: the heading relative to psi(t_c) comes from the
increments (slices of dpsi: psi(t_{j+1}) - psi(t_j), with the gyro bias), the turn inside
a slice from the turn rate w and |psi''| <= turn_accel; d is the distance per slice
(s >= 0) and |e| <= track. Both ways: the heading psi(t_c) from the positions p (the
parts of it whose turn of the window's displacement misses [p](t_b) - [p](t_a) are
removed; psi is an unwrapped angle), and p(t_a), p(t_b) from the heading. Outward
rounded. ContractorNetwork.add(CtcHeadingWindow(window, track, turn_accel, stride),
[p, psi, d, dpsi, w]).)doc")
      .def(py::init<double, double, double, std::size_t>(), py::arg("window"), py::arg("track") = 0.0,
           py::arg("turn_accel") = INFINITY, py::arg("stride") = 1, DOC(CtcHeadingWindow, CtcHeadingWindow))
      .SILLAGE_DEFS(CtcHeadingWindow, window, track, turn_accel, stride)
      .def("__repr__",
           [](const CtcHeadingWindow& c) {
             const auto num = [](double x) { return std::string(py::repr(py::float_(x))); };
             return "CtcHeadingWindow(window=" + num(c.window()) + ", track=" + num(c.track()) +
                    ", turn_accel=" + num(c.turn_accel()) + ", stride=" + std::to_string(c.stride()) + ")";
           })
      .def("contract",
           py::overload_cast<TubeVector&, Tube&, const Tube&, const Tube&, const Tube&>(&CtcHeadingWindow::contract,
                                                                                        py::const_),
           py::arg("p"), py::arg("psi"), py::arg("d"), py::arg("dpsi"), py::arg("w"), nogil,
           DOC(CtcHeadingWindow, contract, TubeVector_Tube_Tube_Tube_Tube));
}

}  // namespace sillage::python
