// CtcHeading (the displacement over each slice from the distance travelled and
// the heading, both ways): contract(p, psi, d, w) on the caller's own tubes, in
// place; a NetworkCtc, so ContractorNetwork.add(CtcHeading(track), [p, psi, d, w])
// binds it. CtcHeadingWindow, the same over windows of slices against the
// heading increments: ContractorNetwork.add(CtcHeadingWindow(...), [p, psi, d, dpsi, w]).
#include <cmath>
#include <cstddef>
#include <string>

#include "bindings.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"

namespace sillage::python {

void init_ctc_heading(py::module_& m) {
  py::class_<CtcHeading, NetworkCtc, std::shared_ptr<CtcHeading>>(m, "CtcHeading", R"doc(
p(t_{k+1}) - p(t_k) = integral over slice k of s (cos, sin)(psi + e), with d_k the
distance (slice k of the tube d, s >= 0), |e| <= track (direction of travel vs
heading) and psi' in w. Both ways: the positions p (a 2-d TubeVector) from the
heading psi, and the heading (slices and gates) from the positions, when the
displacement box excludes 0 and the heading spans less than a half turn over
the slice. Outward rounded. ContractorNetwork.add(CtcHeading(track), [p, psi, d, w]).)doc")
      .def(py::init<double>(), py::arg("track") = 0.0,
           "The contractor with the bound track >= 0 (rad) on the angle between the direction of travel and the "
           "heading (else Error).")
      .def("track", &CtcHeading::track, "The bound on the angle between the direction of travel and the heading.")
      .def("__repr__", [](const CtcHeading& c) { return "CtcHeading(track=" + std::string(py::repr(py::float_(c.track()))) + ")"; })
      .def(
          "contract",
          [](const CtcHeading& c, TubeVector& p, Tube& psi, const Tube& d, const Tube& w) {
            py::gil_scoped_release release;
            return c.contract(p, psi, d, w);
          },
          py::arg("p"), py::arg("psi"), py::arg("d"), py::arg("w"),
          "Contracts the positions p (2 components) and the heading psi in place; d (distance per slice) and w "
          "(bounds of psi') are read. Returns False when no trajectory is left (p and psi are then set empty).");

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
           py::arg("turn_accel") = INFINITY, py::arg("stride") = 1,
           "The contractor over windows of `window` > 0 seconds, one every `stride` >= 1 slices, with the bound "
           "track >= 0 (rad) on the angle between the direction of travel and the heading and turn_accel > 0 "
           "(rad/s^2; inf: none) on the turn acceleration (else Error).")
      .def("window", &CtcHeadingWindow::window, "The length of the windows, in seconds.")
      .def("track", &CtcHeadingWindow::track, "The bound on the angle between the direction of travel and the heading.")
      .def("turn_accel", &CtcHeadingWindow::turn_accel, "The bound on |psi''| (rad/s^2; inf: none).")
      .def("stride", &CtcHeadingWindow::stride, "A window starts every `stride` slices.")
      .def("__repr__",
           [](const CtcHeadingWindow& c) {
             const auto num = [](double x) { return std::string(py::repr(py::float_(x))); };
             return "CtcHeadingWindow(window=" + num(c.window()) + ", track=" + num(c.track()) +
                    ", turn_accel=" + num(c.turn_accel()) + ", stride=" + std::to_string(c.stride()) + ")";
           })
      .def(
          "contract",
          [](const CtcHeadingWindow& c, TubeVector& p, Tube& psi, const Tube& d, const Tube& dpsi, const Tube& w) {
            py::gil_scoped_release release;
            return c.contract(p, psi, d, dpsi, w);
          },
          py::arg("p"), py::arg("psi"), py::arg("d"), py::arg("dpsi"), py::arg("w"),
          "Contracts the positions p (2 components) and the heading psi in place; d (distance per slice), dpsi "
          "(heading increment per slice) and w (bounds of psi') are read. Returns False when no trajectory is "
          "left (p and psi are then set empty).");
}

}  // namespace sillage::python
