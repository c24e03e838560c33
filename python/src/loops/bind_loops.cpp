// Loops in the t-plane (thesis ch. 6): TPlane and Loop, ProofOptions,
// LoopFunction, the zero tests on planar maps (topological_degree,
// newton_test, count_zeros) and the true crossings of a sampled path
// (self_crossings). TPlane runs in C++ on a worker thread without the GIL
// (its components are proven in parallel) and stops on Ctrl-C
// (interruptible.h); the zero tests take either Python callables (run on the
// calling thread) or a LoopFunction (run in C++ the same way as TPlane).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.h"
#include "interruptible.h"
#include "sillage/loops/component_split.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/loop_sivia.h"
#include "sillage/loops/path_crossings.h"
#include "sillage/loops/tplane.h"
#include "sillage/loops/zero_tests.h"

namespace sillage::python {

namespace {

// [f]([t]) from a Python callable returning an IntervalVector, or anything
// IntervalVector(...) accepts (a list, an (n, 2) array): a wrong value raises
// sillage.Error with the constructor's message rather than a bare cast error.
PlaneFunction plane_function(const py::function& f) {
  return [f](const IntervalVector& t) {
    const py::object r = f(t);
    if (py::isinstance<IntervalVector>(r)) return r.cast<IntervalVector>();
    return py::type::of<IntervalVector>()(r).cast<IntervalVector>();
  };
}
// [J]([t]) from a callable returning an IntervalMatrix, a list of rows or an array.
PlaneJacobian plane_jacobian(const py::function& j) {
  return [j](const IntervalVector& t) {
    const py::object r = j(t);
    if (py::isinstance<IntervalMatrix>(r)) return r.cast<IntervalMatrix>();
    return py::type::of<IntervalMatrix>()(r).cast<IntervalMatrix>();
  };
}

// Boxes as a float array (k, 2, 2) of [lb, ub] rows, as Paving.boxes_array: fast plotting.
py::array_t<double> boxes_array(const std::vector<IntervalVector>& boxes) {
  py::array_t<double> a({boxes.size(), std::size_t{2}, std::size_t{2}});
  auto r = a.mutable_unchecked<3>();
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    for (std::size_t d = 0; d < 2; ++d) {
      r(k, d, 0) = boxes[k][d].lb();
      r(k, d, 1) = boxes[k][d].ub();
    }
  }
  return a;
}

std::string optional_str(const std::optional<int>& x) { return x ? std::to_string(*x) : "None"; }

std::string loop_repr(const Loop& l) {
  std::string s = "<Loop t_box " + l.t_box().str() + (l.complete() ? ", complete" : ", partial");
  if (l.degree()) s += ", degree " + std::to_string(*l.degree());
  if (l.count()) s += ", count " + std::to_string(*l.count());
  if (!l.pieces().empty()) s += ", " + std::to_string(l.pieces().size()) + " pieces";
  return s + ">";
}

std::string optional_size_str(const std::optional<std::size_t>& x) { return x ? std::to_string(*x) : "None"; }

}  // namespace

void init_loops(py::module_& m) {
  py::class_<Loop>(m, "Loop", "A loop detection Omega_i of the t-plane and what is known of it.")
      .def("boxes", &Loop::boxes, "Leaves of the outer approximation in this component.")
      .def("boxes_array", [](const Loop& l) { return boxes_array(l.boxes()); },
           "The boxes as a numpy array (k, 2, 2) of [lb, ub] rows.")
      .def("nb_inner", &Loop::nb_inner, "Number of those leaves proven inside the loop set (Inner).")
      .def("t_box", &Loop::t_box, "[t1] x [t2], hull of the boxes.")
      .def("map_box", &Loop::map_box, "Hull of the positions over [t1] and [t2] (after compute_proofs).")
      .def("complete", &Loop::complete, "Strictly inside the t-plane and above its diagonal.")
      .def("degree", &Loop::degree, "Topological degree of f over the component, or None.")
      .def("proven", &Loop::proven, "A loop is proven by the degree test T.")
      .def("proven_newton", &Loop::proven_newton, "A unique loop is proven by the Newton test N.")
      .def("count", &Loop::count, "Exact number of loops (Alg. 10, or the sum over the pieces), or None.")
      .def("pieces", &Loop::pieces,
           "The pieces (Loop) of the component when it was split (degree 0, undetermined or uncounted): disjoint "
           "sub-loops with zero-free boundaries, each with its boxes, t_box, map_box, degree and count.")
      .def("nb_proven_pieces", &Loop::nb_proven_pieces, "Pieces of non-zero degree (each proves a loop).")
      .def("proven_split", &Loop::proven_split, "A loop is proven by T on the component or on one of its pieces.")
      .def("__repr__", &loop_repr);

  py::class_<ProofOptions>(m, "ProofOptions", "Tuning of TPlane.compute_proofs (lengths as fractions of eps).")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "The default tuning (see the fields); newton and count on.")
      .def_readwrite("degree_edge_fraction", &ProofOptions::degree_edge_fraction,
                     "Boundary edges of a detection are bisected for the degree down to this fraction of eps.")
      .def_readwrite("degree_max_evaluations", &ProofOptions::degree_max_evaluations,
                     "Cap on the evaluations of [f] for one degree.")
      .def_readwrite("count_width_fraction", &ProofOptions::count_width_fraction,
                     "zeta of Remark 6.1 as a fraction of eps: boxes are bisected for the Jacobian down to this width.")
      .def_readwrite("count_max_boxes", &ProofOptions::count_max_boxes, "Cap on the refined boxes of one count.")
      .def_readwrite("newton", &ProofOptions::newton, "Run the interval Newton test N (default True).")
      .def_readwrite("newton_inflation", &ProofOptions::newton_inflation,
                     "When N fails on the hull, it is retried on the hull widened by this fraction of its radius (then "
                     "2, 4, 8 times it) while the box stays inside the square, above the diagonal, away from other "
                     "components; 0: the hull only.")
      .def_readwrite("count", &ProofOptions::count, "Run the count of loops, Alg. 10 (default True).")
      .def_readwrite("split", &ProofOptions::split,
                     "Split the complete detections of degree 0, undetermined or uncounted into pieces (default True).")
      .def_readwrite("split_max_levels", &ProofOptions::split_max_levels,
                     "Bisections of the boxes of a piece still to settle (3: down to eps/2.8, inside the detection).")
      .def_readwrite("split_max_boxes", &ProofOptions::split_max_boxes, "Cap on the boxes of a piece being refined.")
      .def_readwrite("budget", &ProofOptions::budget, "For the whole call (sillage.Budget).");

  const py::call_guard<py::gil_scoped_release> nogil;
  py::class_<TPlane>(m, "TPlane",
                     "Loops of a planar trajectory in the t-plane [t0, tf]^2 (thesis ch. 6).\n"
                     "compute_detections: Alg. 6, a paving of {(t1, t2) | t1 < t2, 0 in [f](t1, t2)} with\n"
                     "[f] = integral of [v] over [t1] -> [t2] (6.6) (or (7.28) from positions), Outside by\n"
                     "(6.8)-(6.9), Inner by (6.10); its connected components are the detections.\n"
                     "compute_proofs: degree test, Newton test, count (Alg. 7-10).")
      .def("__repr__",
           [](const TPlane& tp) {
             std::ostringstream s;  // eps as printf's %g
             s << "TPlane(t1=" << tp.domain()[0].str() << ", t2=" << tp.domain()[1].str() << ", eps=" << tp.eps()
               << ", " << tp.nb_detections() << " detections, " << tp.nb_proofs() << " proofs)";
             return s.str();
           })
      .def(py::init<const Interval&>(), py::arg("tdomain"),
           "The t-plane tdomain^2; tdomain bounded with lb < ub (Error otherwise).")
      .def(py::init<const std::shared_ptr<TDomain>&>(), py::arg("tdomain"), "The t-plane [t0, tf]^2 of a TDomain.")
      .def("domain", &TPlane::domain, "The square [t0, tf]^2.")
      .def(
          "compute_detections",
          [](TPlane& tp, double eps, const TubeVector& v, const Budget& b) {
            run_interruptible(b.cancel, [&](const CancelToken& t) { tp.compute_detections(eps, v, with_token(b, t)); });
          },
          py::arg("eps"), py::arg("v"), py::arg("budget") = Budget{},
          "Alg. 6 from a 2-D velocity tube v; the paving's nodes count against budget.")
      .def(
          "compute_detections",
          [](TPlane& tp, double eps, const TubeVector& p, const TubeVector& w, const Budget& b) {
            run_interruptible(b.cancel,
                              [&](const CancelToken& t) { tp.compute_detections(eps, p, w, with_token(b, t)); });
          },
          py::arg("eps"), py::arg("p"), py::arg("w"), py::arg("budget") = Budget{},
          "Alg. 6 with (7.28), from positions p and velocities w.")
      .def(
          "compute_proofs",
          [](TPlane& tp, const TubeVector& v, const ProofOptions& o) {
            run_interruptible(o.budget.cancel, [&](const CancelToken& t) { tp.compute_proofs(v, with_token(o, t)); });
          },
          py::arg("v"), py::arg("options") = ProofOptions{},
          "Degree test T (Theorem 6.1), Newton test N (6.18) and loop count (Alg. 10) on each complete detection, "
          "and the map box of every detection, from the 2-D velocity tube v. Error before compute_detections; "
          "replaces the previous proofs.")
      .def(
          "compute_proofs",
          [](TPlane& tp, const TubeVector& p, const TubeVector& w, const ProofOptions& o) {
            run_interruptible(o.budget.cancel,
                              [&](const CancelToken& t) { tp.compute_proofs(p, w, with_token(o, t)); });
          },
          py::arg("p"), py::arg("w"), py::arg("options") = ProofOptions{},
          "The same proofs from positions p and velocities w (7.28).")
      .def("eps", &TPlane::eps, "The eps of the last detections (0 before).")
      .def("paving", &TPlane::paving, py::return_value_policy::reference_internal,
           "The t-plane paving (6.8)-(6.10): Outside, Inner and Boundary t-boxes.")
      .def("nb_detections", &TPlane::nb_detections, "Number of detections (connected components), complete or not.")
      .def("nb_complete_detections", &TPlane::nb_complete_detections,
           "Number of detections strictly inside the square and above its diagonal.")
      .def("nb_proofs", &TPlane::nb_proofs, "Complete detections proven a loop by the degree test T.")
      .def("nb_newton_proofs", &TPlane::nb_newton_proofs,
           "Complete detections proven a unique loop by the Newton test N.")
      .def("detections", &TPlane::detections,
           "The detections (Loop), ordered by the lower corner of their hull: chronologically by the first passage.")
      .def("proofs", &TPlane::proofs, "The detections proven by T.");

  // The tubes must outlive the LoopFunction and stay unmodified (queries
  // throw otherwise): keep_alive holds them as long as the Python object.
  py::class_<LoopFunction>(m, "LoopFunction",
                           "f(t1, t2) = p(t2) - p(t1) of a planar trajectory: enclosures of f, J_f and positions.")
      .def("__repr__",
           [](const LoopFunction& f) {
             return "LoopFunction(t=" + f.time_domain().str() + (f.has_positions() ? ", from (p, w))" : ", from v)");
           })
      .def(py::init<const TubeVector&>(), py::arg("v"), py::keep_alive<1, 2>(),
           "From a 2-D velocity tube: [f] = integral of [v] over [t1] -> [t2] (6.6).")
      .def(py::init<const TubeVector&, const TubeVector&>(), py::arg("p"), py::arg("w"), py::keep_alive<1, 2>(),
           py::keep_alive<1, 3>(), "From 2-D positions p and velocities w: [f] of (7.28).")
      .def("has_positions", &LoopFunction::has_positions,
           "True when built from positions p and velocities w (7.28), False from v alone (6.6).")
      .def("is_empty", &LoopFunction::is_empty, "Some tube has an empty slice: no trajectory, no loop.")
      .def("time_domain", &LoopFunction::time_domain,
           "[t0, tf] where every tube is defined: the t-plane is its square.")
      .def("__call__", &LoopFunction::operator(), py::arg("t"), "[f]([t1], [t2]).")
      .def("velocity_form", &LoopFunction::velocity_form, py::arg("t"),
           "The velocity form: the integral of [v] from [t1] to [t2] alone (equal to f without positions).")
      .def("jacobian", &LoopFunction::jacobian, py::arg("t"), "[J_f]([t]) = (-[v]([t1]) | [v]([t2])) (6.18).")
      .def("velocity", &LoopFunction::velocity, py::arg("t"),
           "[v]([t]), the velocity hull over the times [t] (within time_domain(), Error otherwise).")
      .def("position", &LoopFunction::position, py::arg("t"),
           "[p]([t]); from v alone, relative to the start of v's time domain.")
      .def("integral_bounds", &LoopFunction::integral_bounds, py::arg("t1"), py::arg("t2"),
           "(ranges of the integral of v^-, of v^+) over t1 in [t1], t2 in [t2] (6.11).");

  py::class_<DegreeOptions>(m, "DegreeOptions", "Tuning of topological_degree.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: min_edge_length 1e-9, max_evaluations 2^20.")
      .def_readwrite("min_edge_length", &DegreeOptions::min_edge_length,
                     "Boundary pieces are bisected until they exclude 0 or are shorter than this.")
      .def_readwrite("max_evaluations", &DegreeOptions::max_evaluations,
                     "Cap on the evaluations of [f] for one degree (an inconclusive result, not an error).")
      .def_readwrite("budget", &DegreeOptions::budget, "Cancellation and time (sillage.Budget); exceeding it raises.");
  py::class_<DegreeResult>(m, "DegreeResult", "The result of topological_degree.")
      .def_readonly("degree", &DegreeResult::degree,
                    "The degree when every boundary piece excludes 0; None otherwise (inconclusive: nothing proven or "
                    "disproven).")
      .def_readonly("nb_evaluations", &DegreeResult::nb_evaluations, "Calls of [f].")
      .def_readonly("nb_pieces", &DegreeResult::nb_pieces, "Boundary pieces of the final cover.")
      .def_readonly("nb_unresolved", &DegreeResult::nb_unresolved,
                    "Pieces with 0 in [f] at the floor, or left unevaluated once max_evaluations was spent.")
      .def("proves_zero", &DegreeResult::proves_zero,
           "True when the degree is known and non-zero: f has a zero in the region.")
      .def("__repr__", [](const DegreeResult& r) {
        return "<DegreeResult degree " + optional_str(r.degree) + ", " + std::to_string(r.nb_evaluations) +
               " evaluations, " + std::to_string(r.nb_unresolved) + " unresolved>";
      });
  // The LoopFunction overloads come first: a LoopFunction is callable, so the
  // py::function ones would accept it too, and call it through Python.
  m.def(
      "topological_degree",
      [](const std::vector<IntervalVector>& boxes, const LoopFunction& f, const DegreeOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          return topological_degree(boxes, f.function(), with_token(o, t));
        });
      },
      py::arg("boxes"), py::arg("f"), py::arg("options") = DegreeOptions{},
      "Degree of the LoopFunction f over a union of 2-D boxes, from [f] on its refined boundary (Theorem 6.1).");
  m.def(
      "topological_degree",
      [](const std::vector<ContourLoop>& loops, const LoopFunction& f, const DegreeOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          return topological_degree(loops, f.function(), with_token(o, t));
        });
      },
      py::arg("loops"), py::arg("f"), py::arg("options") = DegreeOptions{},
      "Degree of the LoopFunction f over the region bounded by oriented contour loops (contour orientation: holes "
      "clockwise).");
  m.def(
      "topological_degree",
      [](const std::vector<IntervalVector>& boxes, const py::function& f, const DegreeOptions& o) {
        return topological_degree(boxes, plane_function(f), o);
      },
      py::arg("boxes"), py::arg("f"), py::arg("options") = DegreeOptions{},
      "Degree of f over a union of 2-D boxes, from [f] on its refined boundary (Theorem 6.1).");
  m.def(
      "topological_degree",
      [](const std::vector<ContourLoop>& loops, const py::function& f, const DegreeOptions& o) {
        return topological_degree(loops, plane_function(f), o);
      },
      py::arg("loops"), py::arg("f"), py::arg("options") = DegreeOptions{},
      "Degree of a Python f(box) -> box over the region bounded by oriented contour loops.");

  py::class_<NewtonOptions>(m, "NewtonOptions", "Tuning of newton_test.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: max_iterations 20.")
      .def_readwrite("max_iterations", &NewtonOptions::max_iterations, "Newton contractions [t] &= N([t]) at most.");
  py::class_<NewtonResult>(m, "NewtonResult", "The result of newton_test.")
      .def_readonly("proven", &NewtonResult::proven, "True when a unique zero of every f enclosed exists in box.")
      .def_readonly("box", &NewtonResult::box, "The contracted box.")
      .def_readonly("nb_iterations", &NewtonResult::nb_iterations, "Newton contractions done.")
      .def("__repr__", [](const NewtonResult& r) {
        return std::string("<NewtonResult ") + (r.proven ? "proven" : "not proven") + ", box " + r.box.str() + ">";
      });
  m.def(
      "newton_test",
      [](const IntervalVector& box, const LoopFunction& f, const NewtonOptions& o) {
        return newton_test(box, f.function(), f.jacobian_function(), o);
      },
      py::arg("box"), py::arg("f"), py::arg("options") = NewtonOptions{}, nogil,
      "Interval Newton test with the Jacobian (6.18) of a LoopFunction.");
  m.def(
      "newton_test",
      [](const IntervalVector& box, const py::function& f, const py::function& j, const NewtonOptions& o) {
        return newton_test(box, plane_function(f), plane_jacobian(j), o);
      },
      py::arg("box"), py::arg("f"), py::arg("jacobian"), py::arg("options") = NewtonOptions{},
      "Interval Newton test: proven when N([t]) lies in the interior of [t].");

  py::class_<CountOptions>(m, "CountOptions", "Tuning of count_zeros.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: min_width 1e-9, max_boxes 2^16.")
      .def_readwrite("min_width", &CountOptions::min_width,
                     "zeta of Remark 6.1: boxes are not bisected below this width.")
      .def_readwrite("max_boxes", &CountOptions::max_boxes,
                     "Cap on the refined boxes (an inconclusive result, not an error).")
      .def_readwrite("budget", &CountOptions::budget,
                     "Cancellation and time (sillage.Budget); each box counts; exceeding it raises.");
  py::class_<CountResult>(m, "CountResult", "The result of count_zeros.")
      .def_readonly("count", &CountResult::count, "Exact number of zeros in the region when proven, else None.")
      .def_readonly("nb_boxes", &CountResult::nb_boxes, "Boxes after the refinement.")
      .def("__repr__", [](const CountResult& r) {
        return "<CountResult count " + (r.count ? std::to_string(*r.count) : std::string("None")) + ", " +
               std::to_string(r.nb_boxes) + " boxes>";
      });
  m.def(
      "count_zeros",
      [](const std::vector<IntervalVector>& boxes, int degree, const LoopFunction& f, const CountOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          return count_zeros(boxes, degree, f.function(), f.jacobian_function(), with_token(o, t));
        });
      },
      py::arg("boxes"), py::arg("degree"), py::arg("f"), py::arg("options") = CountOptions{},
      "Alg. 10 with the Jacobian (6.18) of a LoopFunction.");
  m.def(
      "count_zeros",
      [](const std::vector<IntervalVector>& boxes, int degree, const py::function& f, const py::function& j,
         const CountOptions& o) { return count_zeros(boxes, degree, plane_function(f), plane_jacobian(j), o); },
      py::arg("boxes"), py::arg("degree"), py::arg("f"), py::arg("jacobian"), py::arg("options") = CountOptions{},
      "Alg. 10: the exact number of zeros when det [J] keeps its sign where f may vanish.");

  py::class_<SplitOptions>(m, "SplitOptions", "Tuning of split_region.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: max_levels 8, max_boxes 2^15, count on.")
      .def_readwrite("max_levels", &SplitOptions::max_levels,
                     "Bisections of every box of a piece still to settle (8: boxes 16 times narrower).")
      .def_readwrite("max_boxes", &SplitOptions::max_boxes, "Cap on the boxes of one piece being refined.")
      .def_readwrite("degree", &SplitOptions::degree, "DegreeOptions for the degree of each piece.")
      .def_readwrite("count", &SplitOptions::count, "Count the zeros of each piece (Alg. 10).")
      .def_readwrite("count_options", &SplitOptions::count_options, "CountOptions for the counts.")
      .def_readwrite("deep_margin", &SplitOptions::deep_margin,
                     "A half whose [f] holds 0 farther than this fraction of its width from both bounds is not "
                     "bisected again (cost only; 0: bisect every box).")
      .def_readwrite("budget", &SplitOptions::budget, "For the whole split (sillage.Budget); exceeding it raises.");
  py::class_<SplitPiece>(m, "SplitPiece", "A piece of a split region: disjoint from the others, zero-free boundary.")
      .def_readonly("boxes", &SplitPiece::boxes, "Its boxes.")
      .def_readonly("t_box", &SplitPiece::t_box, "Hull of its boxes.")
      .def_readonly("degree", &SplitPiece::degree, "Degree of f over the piece, or None (undetermined).")
      .def_readonly("count", &SplitPiece::count, "Exact number of zeros in the piece, or None.")
      .def("proves_zero", &SplitPiece::proves_zero, "The degree is known and non-zero: a zero lies in the piece.")
      .def("__repr__", [](const SplitPiece& p) {
        return "<SplitPiece t_box " + p.t_box.str() + ", degree " + optional_str(p.degree) + ", count " +
               optional_size_str(p.count) + ", " + std::to_string(p.boxes.size()) + " boxes>";
      });
  py::class_<SplitResult>(m, "SplitResult", "The result of split_region.")
      .def_readonly("pieces", &SplitResult::pieces, "The pieces (SplitPiece), ordered by the lower corner of their hull.")
      .def_readonly("nb_evaluations", &SplitResult::nb_evaluations, "Evaluations of [f] for the refinement.")
      .def_readonly("nb_levels", &SplitResult::nb_levels, "Deepest refinement level reached.")
      .def("degree", &SplitResult::degree, "Sum of the degrees of the pieces when all are known, else None.")
      .def("count", &SplitResult::count, "Number of zeros in the region when every piece is counted, else None.")
      .def("nb_proven", &SplitResult::nb_proven, "Pieces of non-zero degree.")
      .def("__repr__", [](const SplitResult& r) {
        return "<SplitResult " + std::to_string(r.pieces.size()) + " pieces, degree " + optional_str(r.degree()) +
               ", count " + optional_size_str(r.count()) + ">";
      });
  m.def(
      "split_region",
      [](const std::vector<IntervalVector>& boxes, const LoopFunction& f, const SplitOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          SplitOptions with = with_token(o, t);
          with.inside = [&f](const IntervalVector& b) { return detail::is_inner_box(f, b); };
          return split_region(boxes, f.function(), f.jacobian_function(), with);
        });
      },
      py::arg("boxes"), py::arg("f"), py::arg("options") = SplitOptions{},
      "Splits a union of t-boxes into pieces with zero-free boundaries for a LoopFunction (Inner boxes kept whole).");
  m.def(
      "split_region",
      [](const std::vector<IntervalVector>& boxes, const py::function& f, const py::object& j, const SplitOptions& o) {
        const PlaneJacobian jac = j.is_none() ? PlaneJacobian{} : plane_jacobian(j.cast<py::function>());
        if (!jac && o.count) throw Error("split_region: a jacobian is needed to count (or set options.count = False)");
        return split_region(boxes, plane_function(f), jac, o);
      },
      py::arg("boxes"), py::arg("f"), py::arg("jacobian") = py::none(), py::arg("options") = SplitOptions{},
      "Splits a union of 2-D boxes into pieces with zero-free boundaries: the degree and count of each.");

  py::class_<PathCrossing>(m, "PathCrossing", "A proper self-crossing of a sampled path.")
      .def_readonly("t1", &PathCrossing::t1, "The first passage time (t1 < t2).")
      .def_readonly("t2", &PathCrossing::t2, "The second passage time.")
      .def_readonly("x", &PathCrossing::x, "x of the crossing point.")
      .def_readonly("y", &PathCrossing::y, "y of the crossing point.")
      .def_readonly("segment1", &PathCrossing::segment1, "The segment [k, k+1] of the samples holding t1.")
      .def_readonly("segment2", &PathCrossing::segment2, "The segment [k, k+1] holding t2 (segment1 + 1 < segment2).")
      .def("__repr__", [](const PathCrossing& c) {
        return "<PathCrossing t1=" + std::to_string(c.t1) + " t2=" + std::to_string(c.t2) + ">";
      });
  m.def("self_crossings", &self_crossings, py::arg("t"), py::arg("x"), py::arg("y"), nogil,
        "True crossings (t1 < t2) of the polyline through (t, x, y).");
}

}  // namespace sillage::python
