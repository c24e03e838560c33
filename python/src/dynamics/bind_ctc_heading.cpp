// CtcHeading (the displacement over each slice from the distance travelled and
// the heading, both ways): contract(p, psi, d, w) on the caller's own tubes, in
// place; a NetworkCtc, so ContractorNetwork.add(CtcHeading(track), [p, psi, d, w])
// binds it.
#include <string>

#include "bindings.h"
#include "sillage/dynamics/ctc_heading.h"

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
}

}  // namespace sillage::python
