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
#include <string>
#include <vector>

#include "bindings.h"
#include "interruptible.h"
#include "sillage/loops/loop_function.h"
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
  return s + ">";
}

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
      .def("count", &Loop::count, "Exact number of loops (Alg. 10), or None.")
      .def("__repr__", &loop_repr);

  py::class_<ProofOptions>(m, "ProofOptions", "Tuning of TPlane.compute_proofs (lengths as fractions of eps).")
      .def(py::init<>())
      .def_readwrite("degree_edge_fraction", &ProofOptions::degree_edge_fraction)
      .def_readwrite("degree_max_evaluations", &ProofOptions::degree_max_evaluations)
      .def_readwrite("count_width_fraction", &ProofOptions::count_width_fraction)
      .def_readwrite("count_max_boxes", &ProofOptions::count_max_boxes)
      .def_readwrite("newton", &ProofOptions::newton)
      .def_readwrite("newton_inflation", &ProofOptions::newton_inflation)
      .def_readwrite("count", &ProofOptions::count)
      .def_readwrite("budget", &ProofOptions::budget, "For the whole call (sillage.Budget).");

  const py::call_guard<py::gil_scoped_release> nogil;
  py::class_<TPlane>(m, "TPlane", "Loop detections (Alg. 6) and proofs (Alg. 7-10) in the t-plane.")
      .def(py::init<const Interval&>(), py::arg("tdomain"))
      .def(py::init<const std::shared_ptr<TDomain>&>(), py::arg("tdomain"))
      .def("domain", &TPlane::domain)
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
          py::arg("v"), py::arg("options") = ProofOptions{})
      .def(
          "compute_proofs",
          [](TPlane& tp, const TubeVector& p, const TubeVector& w, const ProofOptions& o) {
            run_interruptible(o.budget.cancel,
                              [&](const CancelToken& t) { tp.compute_proofs(p, w, with_token(o, t)); });
          },
          py::arg("p"), py::arg("w"), py::arg("options") = ProofOptions{})
      .def("eps", &TPlane::eps)
      .def("paving", &TPlane::paving, py::return_value_policy::reference_internal)
      .def("nb_detections", &TPlane::nb_detections)
      .def("nb_complete_detections", &TPlane::nb_complete_detections)
      .def("nb_proofs", &TPlane::nb_proofs)
      .def("nb_newton_proofs", &TPlane::nb_newton_proofs)
      .def("detections", &TPlane::detections)
      .def("proofs", &TPlane::proofs);

  // The tubes must outlive the LoopFunction and stay unmodified (queries
  // throw otherwise): keep_alive holds them as long as the Python object.
  py::class_<LoopFunction>(m, "LoopFunction",
                           "f(t1, t2) = p(t2) - p(t1) of a planar trajectory: enclosures of f, J_f and positions.")
      .def(py::init<const TubeVector&>(), py::arg("v"), py::keep_alive<1, 2>(),
           "From a 2-D velocity tube: [f] = integral of [v] over [t1] -> [t2] (6.6).")
      .def(py::init<const TubeVector&, const TubeVector&>(), py::arg("p"), py::arg("w"), py::keep_alive<1, 2>(),
           py::keep_alive<1, 3>(), "From 2-D positions p and velocities w: [f] of (7.28).")
      .def("has_positions", &LoopFunction::has_positions)
      .def("is_empty", &LoopFunction::is_empty, "Some tube has an empty slice: no trajectory, no loop.")
      .def("time_domain", &LoopFunction::time_domain)
      .def("__call__", &LoopFunction::operator(), py::arg("t"), "[f]([t1], [t2]).")
      .def("velocity_form", &LoopFunction::velocity_form, py::arg("t"))
      .def("jacobian", &LoopFunction::jacobian, py::arg("t"), "[J_f]([t]) = (-[v]([t1]) | [v]([t2])) (6.18).")
      .def("velocity", &LoopFunction::velocity, py::arg("t"))
      .def("position", &LoopFunction::position, py::arg("t"),
           "[p]([t]); from v alone, relative to the start of v's time domain.")
      .def("integral_bounds", &LoopFunction::integral_bounds, py::arg("t1"), py::arg("t2"),
           "(ranges of the integral of v^-, of v^+) over t1 in [t1], t2 in [t2] (6.11).");

  py::class_<DegreeOptions>(m, "DegreeOptions")
      .def(py::init<>())
      .def_readwrite("min_edge_length", &DegreeOptions::min_edge_length)
      .def_readwrite("max_evaluations", &DegreeOptions::max_evaluations)
      .def_readwrite("budget", &DegreeOptions::budget);
  py::class_<DegreeResult>(m, "DegreeResult")
      .def_readonly("degree", &DegreeResult::degree)
      .def_readonly("nb_evaluations", &DegreeResult::nb_evaluations)
      .def_readonly("nb_pieces", &DegreeResult::nb_pieces)
      .def_readonly("nb_unresolved", &DegreeResult::nb_unresolved)
      .def("proves_zero", &DegreeResult::proves_zero)
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
      py::arg("boxes"), py::arg("f"), py::arg("options") = DegreeOptions{});
  m.def(
      "topological_degree",
      [](const std::vector<ContourLoop>& loops, const LoopFunction& f, const DegreeOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          return topological_degree(loops, f.function(), with_token(o, t));
        });
      },
      py::arg("loops"), py::arg("f"), py::arg("options") = DegreeOptions{});
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
      py::arg("loops"), py::arg("f"), py::arg("options") = DegreeOptions{});

  py::class_<NewtonOptions>(m, "NewtonOptions")
      .def(py::init<>())
      .def_readwrite("max_iterations", &NewtonOptions::max_iterations);
  py::class_<NewtonResult>(m, "NewtonResult")
      .def_readonly("proven", &NewtonResult::proven)
      .def_readonly("box", &NewtonResult::box)
      .def_readonly("nb_iterations", &NewtonResult::nb_iterations)
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

  py::class_<CountOptions>(m, "CountOptions")
      .def(py::init<>())
      .def_readwrite("min_width", &CountOptions::min_width)
      .def_readwrite("max_boxes", &CountOptions::max_boxes)
      .def_readwrite("budget", &CountOptions::budget);
  py::class_<CountResult>(m, "CountResult")
      .def_readonly("count", &CountResult::count)
      .def_readonly("nb_boxes", &CountResult::nb_boxes)
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

  py::class_<PathCrossing>(m, "PathCrossing", "A proper self-crossing of a sampled path.")
      .def_readonly("t1", &PathCrossing::t1)
      .def_readonly("t2", &PathCrossing::t2)
      .def_readonly("x", &PathCrossing::x)
      .def_readonly("y", &PathCrossing::y)
      .def_readonly("segment1", &PathCrossing::segment1)
      .def_readonly("segment2", &PathCrossing::segment2)
      .def("__repr__", [](const PathCrossing& c) {
        return "<PathCrossing t1=" + std::to_string(c.t1) + " t2=" + std::to_string(c.t2) + ">";
      });
  m.def("self_crossings", &self_crossings, py::arg("t"), py::arg("x"), py::arg("y"), nogil,
        "True crossings (t1 < t2) of the polyline through (t, x, y).");
}

}  // namespace sillage::python
