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
#include "docstrings.h"
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

// The jacobian of split_region: none, unless options.count needs one (Error naming `where`).
PlaneJacobian python_jacobian(const py::object& j, const SplitOptions& o, const std::string& where) {
  if (!j.is_none()) return plane_jacobian(j.cast<py::function>());
  if (o.count) throw Error(where + ": a jacobian is needed to count (or set options.count = False)");
  return {};
}

// `count` (count_zeros or count_zeros_run) bound as `name` twice: for a
// LoopFunction, on a worker thread (Ctrl-C stops it), and for Python callables.
template <class Count>
void def_count(py::module_& m, const char* name, Count count, const char* loop_doc, const char* python_doc) {
  m.def(
      name,
      [count](const std::vector<IntervalVector>& boxes, int degree, const LoopFunction& f, const CountOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          return count(boxes, degree, f.memoized_function(), f.jacobian_function(), with_token(o, t));
        });
      },
      py::arg("boxes"), py::arg("degree"), py::arg("f"), py::arg("options") = CountOptions{}, loop_doc);
  m.def(
      name,
      [count](const std::vector<IntervalVector>& boxes, int degree, const py::function& f, const py::function& j,
              const CountOptions& o) { return count(boxes, degree, plane_function(f), plane_jacobian(j), o); },
      py::arg("boxes"), py::arg("degree"), py::arg("f"), py::arg("jacobian"), py::arg("options") = CountOptions{},
      python_doc);
}

// `split` (split_region or split_region_run) bound as `name` twice: for a
// LoopFunction, on a worker thread (Ctrl-C stops it), and for Python callables
// (on this thread: they need the GIL).
template <class Split>
void def_split(py::module_& m, const char* name, Split split, const char* loop_doc, const char* python_doc) {
  m.def(
      name,
      [split](const std::vector<IntervalVector>& boxes, const LoopFunction& f, const SplitOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          SplitOptions with = with_token(o, t);
          with.inside = [&f](const IntervalVector& b) { return detail::is_inner_box(f, b); };
          return split(boxes, f.memoized_function(), f.jacobian_function(), with);
        });
      },
      py::arg("boxes"), py::arg("f"), py::arg("options") = SplitOptions{}, loop_doc);
  m.def(
      name,
      [split, name](const std::vector<IntervalVector>& boxes, const py::function& f, const py::object& j,
                    const SplitOptions& o) { return split(boxes, plane_function(f), python_jacobian(j, o, name), o); },
      py::arg("boxes"), py::arg("f"), py::arg("jacobian") = py::none(), py::arg("options") = SplitOptions{},
      python_doc);
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

// A RunResult<T> (run_result.h) as `name`: value (None unless finished), summary, take().
template <class T>
void bind_run_result(py::module_& m, const char* name, const char* doc) {
  using Run = RunResult<T>;
  py::class_<Run>(m, name, doc)
      .def_readonly("value", &Run::value, "The result of a finished run; None for Stopped and Cancelled.")
      .def_readonly("summary", &Run::summary, "Converged, Stopped (the budget in reason) or Cancelled.")
      .def("take", [](const Run& r) { return Run(r).take(); },
           "The value of a finished run; raises BudgetExceeded (Stopped) or Cancelled (Cancelled).")
      .def("__iter__",
           [](const py::object& self) { return py::iter(py::make_tuple(self.attr("value"), self.attr("summary"))); },
           "value, summary = run")
      .def("__repr__", [name](const py::object& self) {
        return std::string(name) + "(value=" + py::repr(self.attr("value")).cast<std::string>() +
               ", summary=" + self.attr("summary").attr("__str__")().cast<std::string>() + ")";
      });
}

}  // namespace

SILLAGE_BINDING(loops, "budget", "interval", "paving", "tdomain", "tube") {
  py::class_<Loop>(m, "Loop", DOC(Loop))
      .SILLAGE_DEF(Loop, boxes)
      .def("boxes_array", [](const Loop& l) { return boxes_array(l.boxes()); },
           "The boxes as a numpy array (k, 2, 2) of [lb, ub] rows.")
      .SILLAGE_DEFS(Loop, nb_inner, t_box, map_box, complete, degree, proven, proven_newton, count, pieces,
                    nb_proven_pieces, proven_split)
      .def("__repr__", &loop_repr);

  py::class_<ProofOptions>(m, "ProofOptions", DOC(ProofOptions))
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "The default tuning (see the fields); newton and count on.")
      .SILLAGE_FIELDS(ProofOptions, degree_edge_fraction, degree_max_evaluations, count_width_fraction,
                      count_max_boxes, newton, newton_inflation, count, split, split_max_levels, split_max_boxes,
                      budget);

  py::class_<TPlane>(m, "TPlane",
                     DOC(TPlane))
      .def("__repr__",
           [](const TPlane& tp) {
             std::ostringstream s;  // eps as printf's %g
             s << "TPlane(t1=" << tp.domain()[0].str() << ", t2=" << tp.domain()[1].str() << ", eps=" << tp.eps()
               << ", " << tp.nb_detections() << " detections, " << tp.nb_proofs() << " proofs)";
             return s.str();
           })
      .def(py::init<const Interval&>(), py::arg("tdomain"),
           DOC(TPlane, TPlane, Interval))
      .def(py::init<const std::shared_ptr<TDomain>&>(), py::arg("tdomain"), DOC(TPlane, TPlane, TDomain))
      .SILLAGE_DEF(TPlane, domain)
      .def(
          "compute_detections",
          [](TPlane& tp, double eps, const TubeVector& v, const Budget& b) {
            run_interruptible(b.cancel, [&](const CancelToken& t) { tp.compute_detections(eps, v, with_token(b, t)); });
          },
          py::arg("eps"), py::arg("v"), py::arg("budget") = Budget{},
          DOC(TPlane, compute_detections, double_TubeVector_Budget))
      .def(
          "compute_detections",
          [](TPlane& tp, double eps, const TubeVector& p, const TubeVector& w, const Budget& b) {
            run_interruptible(b.cancel,
                              [&](const CancelToken& t) { tp.compute_detections(eps, p, w, with_token(b, t)); });
          },
          py::arg("eps"), py::arg("p"), py::arg("w"), py::arg("budget") = Budget{},
          DOC(TPlane, compute_detections, double_TubeVector_TubeVector_Budget))
      .def(
          "compute_detections_run",
          [](TPlane& tp, double eps, const TubeVector& v, const Budget& b) {
            return run_interruptible(
                b.cancel, [&](const CancelToken& t) { return tp.compute_detections_run(eps, v, with_token(b, t)); });
          },
          py::arg("eps"), py::arg("v"), py::arg("budget") = Budget{},
          DOC(TPlane, compute_detections_run))
      .def(
          "compute_detections_run",
          [](TPlane& tp, double eps, const TubeVector& p, const TubeVector& w, const Budget& b) {
            return run_interruptible(b.cancel, [&](const CancelToken& t) {
              return tp.compute_detections_run(eps, p, w, with_token(b, t));
            });
          },
          py::arg("eps"), py::arg("p"), py::arg("w"), py::arg("budget") = Budget{},
          "compute_detections_run from positions p and velocities w (7.28).")
      .def(
          "compute_proofs",
          [](TPlane& tp, const TubeVector& v, const ProofOptions& o) {
            run_interruptible(o.budget.cancel, [&](const CancelToken& t) { tp.compute_proofs(v, with_token(o, t)); });
          },
          py::arg("v"), py::arg("options") = ProofOptions{},
          DOC(TPlane, compute_proofs, TubeVector_ProofOptions))
      .def(
          "compute_proofs",
          [](TPlane& tp, const TubeVector& p, const TubeVector& w, const ProofOptions& o) {
            run_interruptible(o.budget.cancel,
                              [&](const CancelToken& t) { tp.compute_proofs(p, w, with_token(o, t)); });
          },
          py::arg("p"), py::arg("w"), py::arg("options") = ProofOptions{},
          DOC(TPlane, compute_proofs, TubeVector_TubeVector_ProofOptions))
      .SILLAGE_DEF(TPlane, eps)
      .SILLAGE_DEF(TPlane, paving, py::return_value_policy::reference_internal)
      .SILLAGE_DEFS(TPlane, nb_detections, nb_complete_detections, nb_proofs, nb_newton_proofs, detections, proofs);

  // The tubes must outlive the LoopFunction and stay unmodified (queries
  // throw otherwise): keep_alive holds them as long as the Python object.
  py::class_<LoopFunction>(m, "LoopFunction",
                           DOC(LoopFunction))
      .def("__repr__",
           [](const LoopFunction& f) {
             return "LoopFunction(t=" + f.time_domain().str() + (f.has_positions() ? ", from (p, w))" : ", from v)");
           })
      .def(py::init<const TubeVector&>(), py::arg("v"), py::keep_alive<1, 2>(),
           DOC(LoopFunction, LoopFunction, TubeVector))
      .def(py::init<const TubeVector&, const TubeVector&>(), py::arg("p"), py::arg("w"), py::keep_alive<1, 2>(),
           py::keep_alive<1, 3>(), DOC(LoopFunction, LoopFunction, TubeVector_TubeVector))
      .SILLAGE_DEFS(LoopFunction, has_positions, is_empty, time_domain)
      .def("__call__", &LoopFunction::operator(), py::arg("t"), DOC(LoopFunction, op_call))
      .SILLAGE_DEF(LoopFunction, velocity_form, py::arg("t"))
      .SILLAGE_DEF(LoopFunction, jacobian, py::arg("t"))
      .SILLAGE_DEF(LoopFunction, velocity, py::arg("t"))
      .SILLAGE_DEF(LoopFunction, position, py::arg("t"))
      .SILLAGE_DEF(LoopFunction, integral_bounds, py::arg("t1"), py::arg("t2"));

  py::class_<DegreeOptions>(m, "DegreeOptions", DOC(DegreeOptions))
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: min_edge_length 1e-9, max_evaluations 2^20.")
      .SILLAGE_FIELDS(DegreeOptions, min_edge_length, max_evaluations, budget);
  py::class_<DegreeResult>(m, "DegreeResult", DOC(DegreeResult))
      .SILLAGE_READONLY_FIELDS(DegreeResult, degree, nb_evaluations, nb_pieces, nb_unresolved)
      .SILLAGE_DEF(DegreeResult, proves_zero)
      .def("__repr__", [](const DegreeResult& r) {
        return "<DegreeResult degree " + optional_str(r.degree) + ", " + std::to_string(r.nb_evaluations) +
               " evaluations, " + std::to_string(r.nb_unresolved) + " unresolved>";
      });
  // The LoopFunction overloads come first: a LoopFunction is callable, so the
  // py::function ones would accept it too, and call it through Python. They
  // use its memoized form: one per call, which runs on one thread.
  m.def(
      "topological_degree",
      [](const std::vector<IntervalVector>& boxes, const LoopFunction& f, const DegreeOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          return topological_degree(boxes, f.memoized_function(), with_token(o, t));
        });
      },
      py::arg("boxes"), py::arg("f"), py::arg("options") = DegreeOptions{},
      "Degree of the LoopFunction f over a union of 2-D boxes, from [f] on its refined boundary (Theorem 6.1).");
  m.def(
      "topological_degree",
      [](const std::vector<ContourLoop>& loops, const LoopFunction& f, const DegreeOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          return topological_degree(loops, f.memoized_function(), with_token(o, t));
        });
      },
      py::arg("loops"), py::arg("f"), py::arg("options") = DegreeOptions{},
      DOC(topological_degree));
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

  bind_run_result<DegreeResult>(m, "DegreeRun", DOC(DegreeRun));
  m.def(
      "topological_degree_run",
      [](const std::vector<IntervalVector>& boxes, const LoopFunction& f, const DegreeOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& t) {
          return topological_degree_run(boxes, f.memoized_function(), with_token(o, t));
        });
      },
      py::arg("boxes"), py::arg("f"), py::arg("options") = DegreeOptions{},
      DOC(topological_degree_run));
  m.def(
      "topological_degree_run",
      [](const std::vector<IntervalVector>& boxes, const py::function& f, const DegreeOptions& o) {
        return topological_degree_run(boxes, plane_function(f), o);
      },
      py::arg("boxes"), py::arg("f"), py::arg("options") = DegreeOptions{},
      "topological_degree of a Python f(box) -> box with a Summary instead of BudgetExceeded / Cancelled.");

  py::class_<NewtonOptions>(m, "NewtonOptions", DOC(NewtonOptions))
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: max_iterations 20.")
      .SILLAGE_FIELDS(NewtonOptions, max_iterations);
  py::class_<NewtonResult>(m, "NewtonResult", DOC(NewtonResult))
      .SILLAGE_READONLY_FIELDS(NewtonResult, proven, box, nb_iterations)
      .def("__repr__", [](const NewtonResult& r) {
        return std::string("<NewtonResult ") + (r.proven ? "proven" : "not proven") + ", box " + r.box.str() + ">";
      });
  m.def(
      "newton_test",
      [](const IntervalVector& box, const LoopFunction& f, const NewtonOptions& o) {
        return newton_test(box, f.function(), f.jacobian_function(), o);
      },
      py::arg("box"), py::arg("f"), py::arg("options") = NewtonOptions{}, nogil,
      DOC(newton_test));
  m.def(
      "newton_test",
      [](const IntervalVector& box, const py::function& f, const py::function& j, const NewtonOptions& o) {
        return newton_test(box, plane_function(f), plane_jacobian(j), o);
      },
      py::arg("box"), py::arg("f"), py::arg("jacobian"), py::arg("options") = NewtonOptions{},
      "Interval Newton test: proven when N([t]) lies in the interior of [t].");

  py::class_<CountOptions>(m, "CountOptions", DOC(CountOptions))
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: min_width 1e-9, max_boxes 2^16.")
      .SILLAGE_FIELDS(CountOptions, min_width, max_boxes, budget);
  py::class_<CountResult>(m, "CountResult", DOC(CountResult))
      .SILLAGE_READONLY_FIELDS(CountResult, count, nb_boxes)
      .def("__repr__", [](const CountResult& r) {
        return "<CountResult count " + (r.count ? std::to_string(*r.count) : std::string("None")) + ", " +
               std::to_string(r.nb_boxes) + " boxes>";
      });
  def_count(m, "count_zeros", &count_zeros, DOC(count_zeros),
            "Alg. 10: the exact number of zeros when det [J] keeps its sign where f may vanish.");
  bind_run_result<CountResult>(m, "CountRun", DOC(CountRun));
  def_count(m, "count_zeros_run", &count_zeros_run, DOC(count_zeros_run),
            "count_zeros of Python f(box) -> box and jacobian(box) -> matrix with a Summary (CountRun).");

  py::class_<SplitOptions>(m, "SplitOptions", DOC(SplitOptions))
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def(py::init<>(), "Defaults: max_levels 8, max_boxes 2^15, count on.")
      .SILLAGE_FIELDS(SplitOptions, max_levels, max_boxes, degree, count, count_options, deep_margin, budget);
  py::class_<SplitPiece>(m, "SplitPiece", DOC(SplitPiece))
      .SILLAGE_READONLY_FIELDS(SplitPiece, boxes, t_box, degree, count)
      .SILLAGE_DEF(SplitPiece, proves_zero)
      .def("__repr__", [](const SplitPiece& p) {
        return "<SplitPiece t_box " + p.t_box.str() + ", degree " + optional_str(p.degree) + ", count " +
               optional_size_str(p.count) + ", " + std::to_string(p.boxes.size()) + " boxes>";
      });
  py::class_<SplitResult>(m, "SplitResult", DOC(SplitResult))
      .SILLAGE_READONLY_FIELDS(SplitResult, pieces, nb_evaluations, nb_levels)
      .SILLAGE_DEFS(SplitResult, degree, count, nb_proven)
      .def("__repr__", [](const SplitResult& r) {
        return "<SplitResult " + std::to_string(r.pieces.size()) + " pieces, degree " + optional_str(r.degree()) +
               ", count " + optional_size_str(r.count()) + ">";
      });
  def_split(m, "split_region", &split_region, DOC(split_region),
            "Splits a union of 2-D boxes into pieces with zero-free boundaries: the degree and count of each.");
  bind_run_result<SplitResult>(m, "SplitRun", DOC(SplitRun));
  def_split(m, "split_region_run", &split_region_run, DOC(split_region_run),
            "split_region of Python f(box) -> box (and jacobian, needed to count) with a Summary (SplitRun).");

  py::class_<PathCrossing>(m, "PathCrossing", "A proper self-crossing of a sampled path.")
      .SILLAGE_READONLY_FIELDS(PathCrossing, t1)
      .def_readonly("t2", &PathCrossing::t2, "The second passage time.")
      .SILLAGE_READONLY_FIELDS(PathCrossing, x)
      .def_readonly("y", &PathCrossing::y, "y of the crossing point.")
      .SILLAGE_READONLY_FIELDS(PathCrossing, segment1)
      .def_readonly("segment2", &PathCrossing::segment2, "The segment [k, k+1] holding t2 (segment1 + 1 < segment2).")
      .def("__repr__", [](const PathCrossing& c) {
        return "<PathCrossing t1=" + number_text(c.t1) + " t2=" + number_text(c.t2) + ">";
      });
  m.SILLAGE_FN(self_crossings, py::arg("t"), py::arg("x"), py::arg("y"), nogil);
}

}  // namespace sillage::python
