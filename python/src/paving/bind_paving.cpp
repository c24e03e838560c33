// Set inversion: Paving, PavingTag, components and contours, SiviaOptions,
// sivia and kernel_sivia. Calls with C++ functions, contractors and separators
// run on a worker thread without the GIL, in parallel unless options.parallel
// is False, and stop on Ctrl-C (interruptible.h; Python subclasses of Ctc/Sep
// take the GIL in their overrides); Python callables run on the calling thread.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "arg_checks.h"
#include "bindings.h"
#include "interruptible.h"
#include "sillage/paving/sivia_function.h"

namespace sillage::python {

namespace {

py::tuple point(const Point2& p) { return py::make_tuple(p.x, p.y); }

// A box from what a Python callable returned: an IntervalVector, an Interval,
// a number or anything IntervalVector(...) accepts (ArgumentTypeError naming
// `what` otherwise).
IntervalVector as_box(const py::handle& r, const char* what) {
  if (py::isinstance<IntervalVector>(r)) return r.cast<IntervalVector>();
  if (py::isinstance<Interval>(r)) return IntervalVector{r.cast<Interval>()};
  if (py::isinstance<py::float_>(r) || py::isinstance<py::int_>(r)) return IntervalVector{Interval(r.cast<double>())};
  const std::string type = type_name(r);
  if (!py::isinstance<py::str>(r) && !py::isinstance<py::bytes>(r)) {
    try {
      return py::type::of<IntervalVector>()(r).cast<IntervalVector>();
    } catch (const py::error_already_set& e) {
      if (!e.matches(PyExc_TypeError)) throw;  // a ValueError (sillage.Error) says what is wrong
    }
  }
  throw ArgumentTypeError(std::string(what) + " must return an IntervalVector or an Interval, got " + type);
}

// [f]([x]) from a Python callable.
IntervalVector call_box_function(const py::function& f, const IntervalVector& x) {
  return as_box(f(x), "sivia: f");
}

// Runs sivia with the options on a worker thread that Ctrl-C stops.
template <class Run>
Paving interruptible(const SiviaOptions& o, Run run) {
  return run_interruptible(o.budget.cancel, [&](const CancelToken& t) { return run(with_token(o, t)); });
}

// Python callables need the GIL: one thread (Ctrl-C works through them).
SiviaOptions sequential(SiviaOptions o) {
  o.parallel = false;
  return o;
}

// Leaves of a tag as a float array (k, dim, 2) of [lb, ub] rows: fast plotting.
py::array_t<double> boxes_array(const Paving& p, PavingTag tag) {
  const auto leaves = p.leaf_indices(tag);
  py::array_t<double> a({leaves.size(), p.dim(), std::size_t{2}});
  auto r = a.mutable_unchecked<3>();
  for (std::size_t k = 0; k < leaves.size(); ++k) {
    const IntervalVector b = p.node_box(leaves[k]);
    for (std::size_t d = 0; d < p.dim(); ++d) {
      r(k, d, 0) = b[d].lb();
      r(k, d, 1) = b[d].ub();
    }
  }
  return a;
}

}  // namespace

void init_paving(py::module_& m) {
  py::enum_<PavingTag>(m, "PavingTag", "What is known about a leaf of a paving (thesis Fig. 2.11).")
      .value("Inner", PavingTag::Inner, "proven inside X (green)")
      .value("Boundary", PavingTag::Boundary, "undetermined at the precision eps (yellow)")
      .value("Outside", PavingTag::Outside, "proven outside X (blue)");

  py::class_<ContourEdge>(m, "ContourEdge", "An oriented edge from a to b; the region lies on its left.")
      .def_property_readonly("a", [](const ContourEdge& e) { return point(e.a); }, "The start point (x, y).")
      .def_property_readonly("b", [](const ContourEdge& e) { return point(e.b); }, "The end point (x, y).")
      .def("box", &ContourEdge::box, "The edge as a degenerate box [b].")
      .def("length", &ContourEdge::length, "The Euclidean length of the edge.")
      .def("__repr__", [](const ContourEdge& e) {
        return "<ContourEdge " + py::repr(point(e.a)).cast<std::string>() + " -> " +
               py::repr(point(e.b)).cast<std::string>() + ">";
      });

  py::class_<ContourLoop>(m, "ContourLoop",
                          "A closed loop of the boundary: counter-clockwise (outer) or clockwise (hole).")
      .def_readonly("edges", &ContourLoop::edges, "The oriented edges, in order around the loop.")
      .def_readonly("is_hole", &ContourLoop::is_hole, "True for a clockwise loop around a hole.")
      .def("vertices",
           [](const ContourLoop& l) {
             py::list r;
             for (const auto& v : l.vertices()) r.append(point(v));
             return r;
           }, "The vertices in order, a list of points (x, y).")
      .def("length", &ContourLoop::length, "The perimeter of the loop.")
      .def("__len__", [](const ContourLoop& l) { return l.edges.size(); })
      .def("__repr__", [](const ContourLoop& l) { return "<ContourLoop " + l.str() + ">"; });

  py::class_<Component>(m, "Component", "A connected component of the outer approximation (corners connect).")
      .def_readonly("boxes", &Component::boxes, "The leaves of the component.")
      .def_readonly("tags", &Component::tags, "The tag of each leaf (PavingTag).")
      .def_readonly("hull", &Component::hull, "The hull of the leaves.")
      .def_readonly("volume", &Component::volume, "The sum of the leaf volumes.")
      .def("size", &Component::size, "The number of leaves.")
      .def("__len__", &Component::size)
      .def("count", &Component::count, py::arg("tag"), "The number of leaves with this tag.")
      .def("contour", &Component::contour, "Oriented boundary loops (2-D components).")
      .def("__repr__", [](const Component& c) {
        return "<Component of " + std::to_string(c.size()) + " boxes, hull " + c.hull.str() + ">";
      });

  m.def("contour", &contour, py::arg("boxes"), "Oriented boundary loops of a 2-D union of boxes.");
  m.def("connected_components", &connected_components, py::arg("boxes"),
        py::arg("tags") = std::vector<PavingTag>{}, "Connected components of a list of boxes.");

  py::class_<Paving>(m, "Paving", "Result of a set inversion: a binary tree of boxes whose leaves are tagged.")
      .def("dim", &Paving::dim, "The dimension of the boxes.")
      .def("is_empty", &Paving::is_empty, "True for the paving of an empty initial box (no node).")
      .def("domain", &Paving::domain, "The initial box.")
      .def("boxes", &Paving::boxes, py::arg("tag"),
           "The leaves of a tag, in pre-order ('left before right', independent of threads).")
      .def("inner", &Paving::inner, "Boxes proven in X (the inner approximation).")
      .def("boundary", &Paving::boundary, "Undetermined boxes.")
      .def("outer", &Paving::outer, "The outer approximation: inner and boundary boxes.")
      .def("outside", &Paving::outside, "Boxes proven outside X.")
      .def("boxes_array", &boxes_array, py::arg("tag"), "Leaves of a tag as a numpy array (k, dim, 2).")
      .def("nb_nodes", &Paving::nb_nodes, "The number of nodes of the tree (leaves and internal nodes).")
      .def("nb_leaves", &Paving::nb_leaves, "The number of leaves.")
      .def("count", &Paving::count, py::arg("tag"), "The number of leaves with this tag.")
      .def("volume", &Paving::volume, py::arg("tag"),
           "Sum of the leaf volumes of a tag (a floating-point measure, not a set).")
      .def("outer_volume", &Paving::outer_volume, "Volume of the outer approximation X+ = inner & boundary leaves.")
      .def("hull", &Paving::hull, "Hull of the outer approximation.")
      .def("tag_at", &Paving::tag_at, py::arg("point"), "Tag at a point, None outside the initial box.")
      .def("components", &Paving::components,
           "Connected components of the outer approximation X+, in a deterministic order.")
      .def("node_box", &Paving::node_box, py::arg("i"),
           "The box of node i (pre-order index; the left child of i is i + 1).")
      .def("is_leaf", &Paving::is_leaf, py::arg("i"), "True when node i is a leaf.")
      .def("left", &Paving::left, py::arg("i"), "Index of the left child of the internal node i.")
      .def("right", &Paving::right, py::arg("i"), "Index of the right child of the internal node i.")
      .def("tag", &Paving::tag, py::arg("i"), "Tag of the leaf i; Error for an internal node.")
      .def("leaf_indices", &Paving::leaf_indices, py::arg("tag"), "Pre-order indices of the leaves with the given tag.")
      .def("leaves_intersecting", &Paving::leaves_intersecting, py::arg("box"),
           "Indices of the leaves whose closed box intersects box (tree descent).")
      .def("__eq__", &Paving::operator==)
      .def("__ne__", &Paving::operator!=)
      .def("__repr__", &Paving::str);

  py::class_<SiviaOptions>(m, "SiviaOptions", "Options of sivia and kernel_sivia.")
      .def(py::init([](bool parallel, const Budget* budget) {
             SiviaOptions o;
             o.parallel = parallel;
             if (budget) o.budget = *budget;
             return o;
           }),
           py::arg("parallel") = true, py::arg("budget") = nullptr,
           "Options: parallel (oneTBB tasks, default True) and a Budget (default: 10^7 boxes, 1 GiB).")
      .def_readwrite("parallel", &SiviaOptions::parallel,
                     "Grow subtrees as oneTBB tasks (default True). The paving does not depend on it.")
      .def_readwrite("budget", &SiviaOptions::budget,
                     "Limits on the paving's nodes and the time (sillage.Budget; BudgetExceeded when exceeded).")
      .def("__repr__", [](const SiviaOptions& o) {
        return std::string("SiviaOptions(parallel=") + (o.parallel ? "True" : "False") +
               ", budget=" + py::repr(py::cast(o.budget)).cast<std::string>() + ")";
      });
  // Every overload takes options=SiviaOptions() last, as in C++. Calls with a
  // Python callable always run sequentially (they need the GIL), whatever options.parallel.
  const auto opts = [] { return py::arg("options") = SiviaOptions{}; };

  // ---- sivia: Function first, so that a Function never goes to the callable overload ----
  m.def(
      "sivia",
      [](const IntervalVector& x0, const Function& f, const IntervalVector& y, double eps, const SiviaOptions& o) {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia(x0, f, y, eps, io); });
      },
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("eps"), opts(),
      "SIVIA (thesis Alg. 1): paving of x0 for X = f^-1(Y).");
  m.def(
      "sivia",
      [](const IntervalVector& x0, const Function& f, const Interval& y, double eps, const SiviaOptions& o) {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia(x0, f, y, eps, io); });
      },
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("eps"), opts(),
      "SIVIA (Alg. 1) for a scalar f: paving of x0 for X = f^-1([y]).");
  m.def(
      "sivia",
      [](const IntervalVector& x0, const Function& f, const IntervalVector& y, const Ctc& ctc, double eps,
         const SiviaOptions& o) {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia(x0, f, y, ctc, eps, io); });
      },
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("ctc"), py::arg("eps"), opts(),
      "SIVIA coupled with a contractor (thesis Fig. 2.13): undetermined boxes are contracted before bisection.");
  m.def(
      "sivia",
      [](const IntervalVector& x0, const Function& f, const Interval& y, const Ctc& ctc, double eps,
         const SiviaOptions& o) {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia(x0, f, IntervalVector{y}, ctc, eps, io); });
      },
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("ctc"), py::arg("eps"), opts(),
      "SIVIA coupled with a contractor (Fig. 2.13) for a scalar f and an interval y.");
  m.def(
      "sivia",
      [](const IntervalVector& x0, const py::function& f, const IntervalVector& y, double eps, const SiviaOptions& o) {
        return sivia(x0, [&f](const IntervalVector& x) { return call_box_function(f, x); }, y, eps, sequential(o));
      },
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("eps"), opts(),
      "SIVIA with a Python inclusion function f(box) -> box (or Interval); always sequential.");
  m.def(
      "sivia",
      [](const IntervalVector& x0, const py::function& f, const Interval& y, double eps, const SiviaOptions& o) {
        return sivia(x0, [&f](const IntervalVector& x) { return call_box_function(f, x); }, y, eps, sequential(o));
      },
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("eps"), opts(),
      "SIVIA with a Python inclusion function f(box) -> Interval for X = f^-1([y]); always sequential.");
  m.def(
      "sivia",
      [](const IntervalVector& x0, const Sep& sep, double eps, const SiviaOptions& o) {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia(x0, sep, eps, io); });
      },
      py::arg("x0"), py::arg("sep"), py::arg("eps"), opts(),
      "SIVIA with a separator (thesis 2.4.3): removed parts tagged Inner/Outside.");
  m.def(
      "sivia",
      [](const IntervalVector& x0, const Ctc& ctc, double eps, const SiviaOptions& o) {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia(x0, ctc, eps, io); });
      },
      py::arg("x0"), py::arg("ctc"), py::arg("eps"), opts(), "SIVIA with a contractor: an outer approximation.");

  m.def(
      "kernel_sivia",
      [](const IntervalVector& x0, const Function& f_lo, const Function& f_hi, double eps, const SiviaOptions& o) {
        return interruptible(o, [&](const SiviaOptions& io) { return kernel_sivia(x0, f_lo, f_hi, eps, io); });
      },
      py::arg("x0"), py::arg("f_lo"), py::arg("f_hi"), py::arg("eps"), opts(),
      "Kernel SIVIA (thesis Alg. 2) of [f](x) = [f_lo(x), f_hi(x)].");
  m.def(
      "kernel_sivia",
      [](const IntervalVector& x0, const py::function& f, double eps, const SiviaOptions& o) {
        auto bounds = [&f](const IntervalVector& x) {
          const py::object r = f(x);
          if (!py::isinstance<py::tuple>(r) && !py::isinstance<py::list>(r)) {
            throw ArgumentTypeError("kernel_sivia: f must return a pair ([f-]([x]), [f+]([x])), got " + type_name(r));
          }
          const auto t = r.cast<py::sequence>();
          if (t.size() != 2) throw Error("kernel_sivia: f must return a pair ([f-]([x]), [f+]([x]))");
          return std::pair{as_box(t[0], "kernel_sivia: f"), as_box(t[1], "kernel_sivia: f")};
        };
        return kernel_sivia(x0, bounds, eps, sequential(o));
      },
      py::arg("x0"), py::arg("f"), py::arg("eps"), opts(),
      "Kernel SIVIA with a Python f(box) -> (lower, upper) enclosures of the bound functions; always sequential.");
}

}  // namespace sillage::python
