// The slam/ layer (thesis ch. 7): CtcT1T2 (Alg. 11), CtcOmega (Alg. 12),
// CtcPImpliesZ (Alg. 13-14) with its rows (Table 7.2), temporal_slam
// (Alg. 15), the bathymetric observation (7.29)-(7.30).
// Contractions run with the GIL released.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "sillage/slam/ctc_omega.h"
#include "sillage/slam/ctc_p_implies_z.h"
#include "sillage/slam/ctc_t1t2.h"
#include "sillage/slam/observation.h"
#include "sillage/slam/slam_figures.h"
#include "sillage/slam/temporal_slam.h"
#include "sillage/expr/function.h"

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
      .def(
          "hull",
          [](const CtcOmega& c, const std::vector<IntervalVector>& boxes, const TubeVector& p, const TubeVector& w) {
            py::gil_scoped_release unlocked;
            TubeVector work = p;
            return c.hull(boxes, p, w, work);
          },
          py::arg("boxes"), py::arg("p"), py::arg("w"),
          "What contract would do, without doing it: an OmegaHull (the narrowed gates and slices and their values). "
          "p is left as it is; OmegaHull.apply_to(q) intersects it into a tube q.")
      .def("__repr__", [](const CtcOmega&) { return std::string("<CtcOmega>"); });

  py::class_<OmegaHull::Atom>(m, "OmegaHullAtom", "One gate or slice narrowed by CtcOmega.hull.")
      .def_readonly("component", &OmegaHull::Atom::component, "Component of the tube vector.")
      .def_readonly("atom", &OmegaHull::Atom::atom, "2k: gate k, 2k + 1: slice k.")
      .def_readonly("value", &OmegaHull::Atom::value, "Its new value (the hull over the consistent boxes).")
      .def("__repr__", [](const OmegaHull::Atom& a) {
        return "OmegaHullAtom(component=" + std::to_string(a.component) + ", " + (a.atom % 2 ? "slice " : "gate ") +
               std::to_string(a.atom / 2) + ", " + a.value.str() + ")";
      });
  py::class_<OmegaHull>(m, "OmegaHull", "The sparse result of CtcOmega.hull: the atoms it narrows, or empty.")
      .def_readonly("empty", &OmegaHull::empty, "No box is consistent: the tube would be emptied.")
      .def_readonly("atoms", &OmegaHull::atoms, "The narrowed atoms, sorted by (component, atom).")
      .def_readonly("nb_boxes", &OmegaHull::nb_boxes, "Boxes of the component.")
      .def_readonly("nb_consistent", &OmegaHull::nb_consistent, "Boxes visited whose contraction is consistent.")
      .def_readonly("nb_touched", &OmegaHull::nb_touched, "Atoms touched, summed over the boxes (the cost).")
      .def(
          "apply_to", [](const OmegaHull& h, TubeVector& q) { return h.apply_to(q); }, py::arg("q"),
          "q &= the hull (emptied if empty). Returns False if q is empty after.")
      .def("__repr__", [](const OmegaHull& h) {
        return "OmegaHull(empty=" + std::string(h.empty ? "True" : "False") + ", " + std::to_string(h.atoms.size()) +
               " atoms, " + std::to_string(h.nb_consistent) + "/" + std::to_string(h.nb_boxes) + " boxes consistent)";
      });

  py::class_<SlamRow>(m, "SlamRow", "One iteration of C_{p=>z} or of the temporal SLAM (a row of thesis Table 7.2).")
      .def(py::init<>(), "An empty row.")
      .def_readonly("iteration", &SlamRow::iteration, "1, 2, ...")
      .def_readonly("fast", &SlamRow::fast, "Alg. 14 (True) or Alg. 13 (False).")
      .def_readonly("nb_detections", &SlamRow::nb_detections, "Complete loop detections of the t-plane.")
      .def_readonly("nb_proofs", &SlamRow::nb_proofs, "Detections proven to hold a loop (degree test).")
      .def_readonly("seconds", &SlamRow::seconds, "Wall-clock time of the iteration.")
      .def_readonly("cumulated_seconds", &SlamRow::cumulated_seconds, "Time since the first iteration.")
      .def_readonly("contraction_tf", &SlamRow::contraction_tf, "1 - width(p(t_f)) / its input width (summed).")
      .def_readonly("contraction_t0", &SlamRow::contraction_t0, "The same at t_0.")
      .def_readonly("nb_atoms_touched", &SlamRow::nb_atoms_touched, "Gates and slices C_Omega worked on.")
      .def("__repr__", [](const SlamRow& r) { return to_string(r); });

  py::class_<CtcPImpliesZ, NetworkCtc, std::shared_ptr<CtcPImpliesZ>>(
      m, "CtcPImpliesZ",
      "The inter-temporal implication contractor C_{p=>z} (thesis (7.9), Alg. 13, fast=True: Alg. 14):\n"
      "p(t1) = p(t2) => z(t1) = z(t2), p' = w. contract(p, w, z) contracts the 2-D TubeVector p to a fixed\n"
      "point and returns one SlamRow per iteration; ContractorNetwork.add(CtcPImpliesZ(eps), [p, w, z]) binds it.")
      .def(py::init<double, bool>(), py::arg("eps"), py::arg("fast") = false,
           "The contractor; eps > 0 is the width of the t-boxes (about the time step).")
      .def_property_readonly("eps", &CtcPImpliesZ::eps, "The width of the t-boxes.")
      .def_property_readonly("fast", &CtcPImpliesZ::fast, "Alg. 14 (the hull of each component) or Alg. 13.")
      .def("set_ratio", &CtcPImpliesZ::set_ratio, py::arg("ratio"),
           "The fixed point: stop when no gate or slice of p shrinks by more than ratio (in [0, 1)).")
      .def("set_max_iterations", &CtcPImpliesZ::set_max_iterations, py::arg("n"), "A cap on the iterations (>= 1).")
      .def(
          "contract",
          [](const CtcPImpliesZ& c, TubeVector& p, const TubeVector& w, const TubeVector& z) {
            py::gil_scoped_release unlocked;
            return c.contract(p, w, z);
          },
          py::arg("p"), py::arg("w"), py::arg("z"),
          "Contracts the 2-D TubeVector p in place (w its derivative, z the observations, a TubeVector of any "
          "dimension); returns the list of SlamRow, one per iteration. p is emptied when the observations "
          "contradict a proven loop.")
      .def(
          "contract",
          [](const CtcPImpliesZ& c, TubeVector& p, const TubeVector& w, const Tube& z) {
            py::gil_scoped_release unlocked;
            return c.contract(p, w, z);
          },
          py::arg("p"), py::arg("w"), py::arg("z"), "The same with a scalar observation Tube z.")
      .def("__repr__", [](const CtcPImpliesZ& c) {
        return "CtcPImpliesZ(eps=" + py::repr(py::float_(c.eps())).cast<std::string>() +
               ", fast=" + (c.fast() ? "True" : "False") + ")";
      });

  py::class_<TemporalSlamOptions>(m, "TemporalSlamOptions", "Options of temporal_slam.")
      .def(py::init<>(), "eps=0.1, fast and accurate both on, max_rounds=20.")
      .def_readwrite("eps", &TemporalSlamOptions::eps, "Width of the t-boxes (about the time step).")
      .def_readwrite("fast", &TemporalSlamOptions::fast, "Run Alg. 14 to its fixed point.")
      .def_readwrite("accurate", &TemporalSlamOptions::accurate, "Then Alg. 13 to its fixed point.")
      .def_readwrite("max_rounds", &TemporalSlamOptions::max_rounds, "Cap on the rounds per algorithm.")
      .def_readwrite("on_iteration", &TemporalSlamOptions::on_iteration,
                     "None, or a callable(row, p) called after every iteration of C_{p=>z} with its SlamRow and a "
                     "copy of the contracted p (2-D TubeVector): to check the truth or keep snapshots.")
      .def("__repr__", [](const py::object& self) { return fields_repr(self); });

  m.def(
      "temporal_slam",
      [](TubeVector& x, TubeVector& v, const TubeVector& u, const TubeVector& z, const Function& f, const Function& h,
         const TemporalSlamOptions& o) {
        py::gil_scoped_release unlocked;
        return temporal_slam(x, v, u, z, f, h, o);
      },
      py::arg("x"), py::arg("v"), py::arg("u"), py::arg("z"), py::arg("f"), py::arg("h"),
      py::arg("options") = TemporalSlamOptions(),
      "The temporal SLAM of thesis Alg. 15: contracts the state tube x and its derivative v in place from\n"
      "v = f(x, u), x' = v, p = h(x) (h linear, 2 outputs), w = h(v) and p(t1) = p(t2) => z(t1) = z(t2);\n"
      "fast (Alg. 14) then accurate (Alg. 13), each to its fixed point. Returns the list of SlamRow.");

  py::class_<ThicknessCurve>(m, "ThicknessCurve", "One curve of slam_thickness_figure: a tube, a legend, a colour.")
      .def(py::init<TubeVector, std::string, std::string>(), py::arg("p"), py::arg("label"), py::arg("colour"),
           "The curve of p (its components 0 and 1), labelled, in an SVG colour.")
      .def_readwrite("p", &ThicknessCurve::p, "The tube (components 0 and 1 measured).")
      .def_readwrite("label", &ThicknessCurve::label, "The legend.")
      .def_readwrite("colour", &ThicknessCurve::colour, "The SVG colour.")
      .def("__repr__", [](const ThicknessCurve& c) { return "ThicknessCurve(label='" + c.label + "', colour='" + c.colour + "')"; });
  m.def("slam_thickness_figure", &slam_thickness_figure, py::arg("curves"),
        py::arg("title") = "Thickness of [p](t): diagonal of [p1] x [p2]", py::arg("width_px") = 700,
        py::arg("height_px") = 300,
        "The thickness graph of thesis Fig. 7.17: the diagonal of [p1] x [p2] per slice of every curve, one axis.");
  m.def("slam_map_figure", &slam_map_figure, py::arg("mission"), py::arg("dead_reckoning"), py::arg("slam"),
        py::arg("tf_boxes"), py::arg("title") = "Temporal SLAM: dead reckoning, SLAM, truth, [p](t_f)",
        py::arg("width_px") = 600,
        "The mission map of thesis Fig. 7.16: dead-reckoning tube, SLAM tube, truth, successive boxes [p](t_f).");

  m.def("tide_tube", &tide_tube, py::arg("tdomain"), py::arg("tide"), "The tide as a Tube on tdomain.");
  m.def("bathymetric_observation", &bathymetric_observation, py::arg("z_alt"), py::arg("z_depth"), py::arg("tide"),
        "z = z_alt + z_depth + tide (thesis (7.30)), slice- and gate-wise, each term with its own bounded error.");
}

}  // namespace sillage::python
