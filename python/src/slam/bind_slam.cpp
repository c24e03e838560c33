// The slam/ layer (thesis ch. 7): CtcT1T2 (Alg. 11), CtcOmega (Alg. 12),
// CtcPImpliesZ (Alg. 13-14) with its rows (Table 7.2), temporal_slam
// (Alg. 15), the bathymetric observation (7.29)-(7.30).
// Contractions run with the GIL released.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "docstrings.h"
#include "interruptible.h"
#include "sillage/expr/function.h"
#include "sillage/slam/ctc_omega.h"
#include "sillage/slam/ctc_p_implies_z.h"
#include "sillage/slam/ctc_t1t2.h"
#include "sillage/slam/observation.h"
#include "sillage/missions/slam_figures.h"
#include "sillage/slam/temporal_slam.h"

namespace sillage::python {

SILLAGE_BINDING(slam, "budget", "cn", "expr", "interval", "tube") {
  py::class_<CtcT1T2>(m, "CtcT1T2", DOC(CtcT1T2))
      .def(py::init<double, std::size_t>(), py::arg("ratio") = 1e-3, py::arg("max_passes") = 100, DOC(CtcT1T2, CtcT1T2))
      .SILLAGE_PROPERTIES(CtcT1T2, ratio, max_passes)
      .def("contract",
           py::overload_cast<Interval&, Interval&, TubeVector&, const TubeVector&>(&CtcT1T2::contract, py::const_),
           py::arg("t1").noconvert(), py::arg("t2").noconvert(), py::arg("p"), py::arg("w"), nogil,
           DOC(CtcT1T2, contract, Interval_Interval_TubeVector_TubeVector))
      .def("contract", py::overload_cast<Interval&, Interval&, Tube&, const Tube&>(&CtcT1T2::contract, py::const_),
           py::arg("t1").noconvert(), py::arg("t2").noconvert(), py::arg("p"), py::arg("w"), nogil,
           DOC(CtcT1T2, contract, Interval_Interval_Tube_Tube))
      .def("__repr__", [](const CtcT1T2& c) {
        return "CtcT1T2(ratio=" + py::repr(py::float_(c.ratio())).cast<std::string>() + ", max_passes=" + std::to_string(c.max_passes()) + ")";
      });

  // OmegaHull before CtcOmega, whose hull() returns one.
  py::class_<OmegaHull::Atom>(m, "OmegaHullAtom", DOC(Atom))
      .def_readonly("component", &OmegaHull::Atom::component, DOC(Atom, component))
      .def_readonly("atom", &OmegaHull::Atom::atom, DOC(Atom, atom))
      .def_readonly("value", &OmegaHull::Atom::value, DOC(Atom, value))
      .def("__repr__", [](const OmegaHull::Atom& a) {
        return "OmegaHullAtom(component=" + std::to_string(a.component) + ", " + (a.atom % 2 ? "slice " : "gate ") +
               std::to_string(a.atom / 2) + ", " + a.value.str() + ")";
      });
  py::class_<OmegaHull>(m, "OmegaHull", DOC(OmegaHull))
      .SILLAGE_READONLY_FIELDS(OmegaHull, empty, atoms, nb_boxes, nb_consistent, nb_touched)
      .def(
          "apply_to", [](const OmegaHull& h, TubeVector& q) { return h.apply_to(q); }, py::arg("q"),
          DOC(OmegaHull, apply_to))
      .def("__repr__", [](const OmegaHull& h) {
        return "OmegaHull(empty=" + std::string(h.empty ? "True" : "False") + ", " + std::to_string(h.atoms.size()) +
               " atoms, " + std::to_string(h.nb_consistent) + "/" + std::to_string(h.nb_boxes) + " boxes consistent)";
      });

  py::class_<CtcOmega>(m, "CtcOmega", DOC(CtcOmega))
      .def(py::init([](const CtcT1T2& c) { return CtcOmega(c); }), py::arg("t1t2") = CtcT1T2(), DOC(CtcOmega, CtcOmega))
      .SILLAGE_DEF(CtcOmega, contract, py::arg("boxes"), py::arg("p"), py::arg("w"), nogil)
      .def(
          "hull",
          [](const CtcOmega& c, const std::vector<IntervalVector>& boxes, const TubeVector& p, const TubeVector& w) {
            py::gil_scoped_release unlocked;
            TubeVector work = p;
            return c.hull(boxes, p, w, work);
          },
          py::arg("boxes"), py::arg("p"), py::arg("w"), DOC(CtcOmega, hull))
      .def("__repr__", [](const CtcOmega&) { return std::string("<CtcOmega>"); });

  py::class_<SlamRow>(m, "SlamRow", DOC(SlamRow))
      .def(py::init<>(), "An empty row.")
      .SILLAGE_READONLY_FIELDS(SlamRow, iteration, fast, nb_detections, nb_proofs, seconds, cumulated_seconds,
                               contraction_tf, contraction_t0, nb_atoms_touched)
      .def("__repr__", [](const SlamRow& r) { return to_string(r); });

  py::class_<CtcPImpliesZ, NetworkCtc, std::shared_ptr<CtcPImpliesZ>>(
      m, "CtcPImpliesZ",
      DOC(CtcPImpliesZ))
      .def(py::init<double, bool>(), py::arg("eps"), py::arg("fast") = false,
           DOC(CtcPImpliesZ, CtcPImpliesZ))
      .SILLAGE_PROPERTIES(CtcPImpliesZ, eps, fast)
      .SILLAGE_DEF(CtcPImpliesZ, set_ratio, py::arg("ratio"))
      .SILLAGE_DEF(CtcPImpliesZ, set_max_iterations, py::arg("n"))
      // On a worker thread: Ctrl-C (or `cancel`) stops it within a t-box.
      .def(
          "contract",
          [](const CtcPImpliesZ& c, TubeVector& p, const TubeVector& w, const TubeVector& z,
             const CancelToken* cancel) {
            return run_interruptible(cancel, [&](const CancelToken& t) { return c.contract(p, w, z, t); });
          },
          py::arg("p"), py::arg("w"), py::arg("z"), py::arg("cancel") = nullptr,
          DOC(CtcPImpliesZ, contract, TubeVector_TubeVector_TubeVector_CancelToken))
      .def(
          "contract",
          [](const CtcPImpliesZ& c, TubeVector& p, const TubeVector& w, const Tube& z, const CancelToken* cancel) {
            return run_interruptible(cancel, [&](const CancelToken& t) { return c.contract(p, w, z, t); });
          },
          py::arg("p"), py::arg("w"), py::arg("z"), py::arg("cancel") = nullptr,
          DOC(CtcPImpliesZ, contract, TubeVector_TubeVector_Tube_CancelToken))
      .def(
          "iterate",
          [](const CtcPImpliesZ& c, TubeVector& p, const TubeVector& w, const TubeVector& z, SlamRow& row,
             const CancelToken* cancel) {
            return run_interruptible(cancel, [&](const CancelToken& t) { return c.iterate(p, w, z, row, t); });
          },
          py::arg("p"), py::arg("w"), py::arg("z"), py::arg("row"), py::arg("cancel") = nullptr,
          DOC(CtcPImpliesZ, iterate))
      .def("__repr__", [](const CtcPImpliesZ& c) {
        return "CtcPImpliesZ(eps=" + py::repr(py::float_(c.eps())).cast<std::string>() +
               ", fast=" + (c.fast() ? "True" : "False") + ")";
      });

  py::class_<TemporalSlamOptions>(m, "TemporalSlamOptions", DOC(TemporalSlamOptions))
      .def(py::init<>(), "eps=0.1, fast and accurate both on, max_rounds=20.")
      .SILLAGE_FIELDS(TemporalSlamOptions, eps, fast, accurate, max_rounds, on_iteration, cancel, progress)
      .def("__repr__", &fields_repr);

  m.def(
      "temporal_slam",
      [](TubeVector& x, TubeVector& v, const TubeVector& u, const TubeVector& z, const Function& f, const Function& h,
         const TemporalSlamOptions& o) {
        TemporalSlamOptions with = o;  // copied with the GIL: it may hold a Python callback
        return run_interruptible(o.cancel, [&](const CancelToken& token) {
          with.cancel = token;
          return temporal_slam(x, v, u, z, f, h, with);
        });
      },
      py::arg("x"), py::arg("v"), py::arg("u"), py::arg("z"), py::arg("f"), py::arg("h"),
      py::arg("options") = TemporalSlamOptions(),
      DOC(temporal_slam));
  py::class_<TemporalSlamResult>(m, "TemporalSlamResult", DOC(TemporalSlamResult))
      .SILLAGE_READONLY_FIELDS(TemporalSlamResult, rows, summary)
      .def("__iter__",
           [](const py::object& self) { return py::iter(py::make_tuple(self.attr("rows"), self.attr("summary"))); },
           "rows, summary = result")
      .def("__repr__", [](const TemporalSlamResult& r) {
        return "TemporalSlamResult(" + std::to_string(r.rows.size()) + " rows, summary=" + r.summary.str() + ")";
      });
  m.def(
      "temporal_slam_run",
      [](TubeVector& x, TubeVector& v, const TubeVector& u, const TubeVector& z, const Function& f, const Function& h,
         const TemporalSlamOptions& o) {
        TemporalSlamOptions with = o;  // copied with the GIL: it may hold Python callbacks
        return run_interruptible(o.cancel, [&](const CancelToken& token) {
          with.cancel = token;
          return temporal_slam_run(x, v, u, z, f, h, with);
        });
      },
      py::arg("x"), py::arg("v"), py::arg("u"), py::arg("z"), py::arg("f"), py::arg("h"),
      py::arg("options") = TemporalSlamOptions(),
      DOC(temporal_slam_run));

  py::class_<ThicknessCurve>(m, "ThicknessCurve", DOC(ThicknessCurve))
      .def(py::init<TubeVector, std::string, std::string>(), py::arg("p"), py::arg("label"), py::arg("colour"),
           "The curve of p (its components 0 and 1), labelled, in an SVG colour.")
      .SILLAGE_FIELDS(ThicknessCurve, p, label, colour)
      .def("__repr__", [](const ThicknessCurve& c) { return "ThicknessCurve(label='" + c.label + "', colour='" + c.colour + "')"; });
  m.SILLAGE_FN(slam_thickness_figure, py::arg("curves"),
               py::arg("title") = "Thickness of [p](t): diagonal of [p1] x [p2]", py::arg("width_px") = 700,
               py::arg("height_px") = 300);
  m.SILLAGE_FN(slam_map_figure, py::arg("mission"), py::arg("dead_reckoning"), py::arg("slam"), py::arg("tf_boxes"),
               py::arg("title") = "Temporal SLAM: dead reckoning, SLAM, truth, [p](t_f)", py::arg("width_px") = 600);

  m.SILLAGE_FN(tide_tube, py::arg("tdomain"), py::arg("tide"));
  m.SILLAGE_FN(bathymetric_observation, py::arg("z_alt"), py::arg("z_depth"), py::arg("tide"));
}

}  // namespace sillage::python
