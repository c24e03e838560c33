// Set inversion: Paving, PavingTag, components and contours, SiviaOptions,
// sivia and kernel_sivia. Calls with C++ functions, contractors and separators
// run on a worker thread without the GIL, in parallel unless options.parallel
// is False, and stop on Ctrl-C (interruptible.h; Python subclasses of Ctc/Sep
// take the GIL in their overrides); Python callables run on the calling thread.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstring>
#include <optional>
#include <string>

#include "arg_checks.h"
#include "bindings.h"
#include "docstrings.h"
#include "interruptible.h"
#include "sillage/paving/paving_join.h"
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
SiviaResult interruptible(const SiviaOptions& o, Run run) {
  return run_interruptible(o.budget.cancel, [&](const CancelToken& t) { return run(with_token(o, t)); });
}

// Registers one variant twice: `name` returns the paving (raising
// BudgetExceeded or Cancelled, as in C++), `run_name` the SiviaResult.
template <class... Args, class... Extra>
void def_sivia(py::module_& m, const char* name, const char* run_name, SiviaResult (*run)(Args...),
               const char* doc, const char* run_doc, const Extra&... extra) {
  m.def(name, [run](Args... a) { return run(std::forward<Args>(a)...).take(); }, extra..., doc);
  m.def(run_name, run, extra..., run_doc);
}

// Python callables need the GIL: one thread (Ctrl-C works through them).
SiviaOptions sequential(SiviaOptions o) {
  o.parallel = false;
  return o;
}

// A paving's pickled state: (dim, right offsets, kinds, bounds) as bytes, bit for bit.
py::tuple paving_state(const Paving& p) {
  const PavingArrays a = paving_arrays(p);
  const auto bytes = [](const auto& v) {
    return py::bytes(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(v[0]));
  };
  return py::make_tuple(a.dim, bytes(a.right), bytes(a.kind), bytes(a.bounds));
}

template <class T>
std::vector<T> from_bytes(const py::bytes& b) {
  char* data = nullptr;
  Py_ssize_t size = 0;
  if (PyBytes_AsStringAndSize(b.ptr(), &data, &size) != 0) throw py::error_already_set();
  const auto n = static_cast<std::size_t>(size);
  if (n % sizeof(T)) throw Error("Paving: a pickled state whose arrays are cut short");
  std::vector<T> v(n / sizeof(T));
  std::memcpy(v.data(), data, n);  // read in place: no copy of the bytes first
  return v;
}

Paving paving_of_state(const py::tuple& t) {
  if (t.size() != 4) throw Error("Paving: a pickled state of " + std::to_string(t.size()) + " items, expected 4");
  PavingArrays a;
  a.dim = t[0].cast<std::size_t>();
  a.right = from_bytes<std::uint32_t>(t[1]);
  a.kind = from_bytes<std::uint8_t>(t[2]);
  a.bounds = from_bytes<double>(t[3]);
  return paving_from_arrays(a);
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

SILLAGE_BINDING(paving, "budget", "ctc", "expr", "interval") {
  py::enum_<PavingTag>(m, "PavingTag", DOC(PavingTag))
      .value("Inner", PavingTag::Inner, DOC(PavingTag, Inner))
      .value("Boundary", PavingTag::Boundary, DOC(PavingTag, Boundary))
      .value("Outside", PavingTag::Outside, DOC(PavingTag, Outside));

  py::class_<ContourEdge>(m, "ContourEdge", DOC(ContourEdge))
      .def_property_readonly("a", [](const ContourEdge& e) { return point(e.a); }, "The start point (x, y).")
      .def_property_readonly("b", [](const ContourEdge& e) { return point(e.b); }, DOC(ContourEdge, b))
      .SILLAGE_DEFS(ContourEdge, box, length)
      .def("__repr__", [](const ContourEdge& e) {
        return "<ContourEdge " + py::repr(point(e.a)).cast<std::string>() + " -> " +
               py::repr(point(e.b)).cast<std::string>() + ">";
      });

  py::class_<ContourLoop>(m, "ContourLoop",
                          DOC(ContourLoop))
      .SILLAGE_READONLY_FIELDS(ContourLoop, edges, is_hole)
      .def("vertices",
           [](const ContourLoop& l) {
             py::list r;
             for (const auto& v : l.vertices()) r.append(point(v));
             return r;
           }, DOC(ContourLoop, vertices))
      .SILLAGE_DEF(ContourLoop, length)
      .def("__len__", [](const ContourLoop& l) { return l.edges.size(); })
      .def("__repr__", [](const ContourLoop& l) { return "<ContourLoop " + l.str() + ">"; });

  py::class_<Component>(m, "Component", DOC(Component))
      .SILLAGE_READONLY_FIELDS(Component, boxes, tags, hull, volume)
      .SILLAGE_DEF(Component, size)
      .def("__len__", &Component::size)
      .SILLAGE_DEF(Component, count, py::arg("tag"))
      .SILLAGE_DEF(Component, contour)
      .def("__repr__", [](const Component& c) {
        return "<Component of " + std::to_string(c.size()) + " boxes, hull " + c.hull.str() + ">";
      });

  m.def("contour", [](const std::vector<IntervalVector>& boxes) { return contour(boxes); }, py::arg("boxes"),
        DOC(contour));
  m.SILLAGE_FN(connected_components, py::arg("boxes"), py::arg("tags") = std::vector<PavingTag>{});

  py::class_<Paving>(m, "Paving", DOC(Paving))
      .SILLAGE_DEFS(Paving, dim, is_empty, domain)
      .SILLAGE_DEF(Paving, boxes, py::arg("tag"))
      .SILLAGE_DEFS(Paving, inner, boundary, outer, outside)
      .def("boxes_array", &boxes_array, py::arg("tag"), "Leaves of a tag as a numpy array (k, dim, 2).")
      .SILLAGE_DEFS(Paving, nb_nodes, nb_leaves)
      .SILLAGE_DEF(Paving, count, py::arg("tag"))
      .SILLAGE_DEF(Paving, volume, py::arg("tag"))
      .SILLAGE_DEFS(Paving, outer_volume, hull)
      .SILLAGE_DEF(Paving, tag_at, py::arg("point"))
      .def("components", [](const Paving& p) { return p.components(); },
           DOC(Paving, components))
      .SILLAGE_DEF(Paving, node_box, py::arg("i"))
      .SILLAGE_DEF(Paving, is_leaf, py::arg("i"))
      .SILLAGE_DEF(Paving, left, py::arg("i"))
      .SILLAGE_DEF(Paving, right, py::arg("i"))
      .SILLAGE_DEF(Paving, tag, py::arg("i"))
      .SILLAGE_DEF(Paving, leaf_indices, py::arg("tag"))
      .SILLAGE_DEF(Paving, leaves_intersecting, py::arg("box"))
      .def(py::pickle(&paving_state, &paving_of_state))
      .def("__eq__", &Paving::operator==)
      .def("__ne__", &Paving::operator!=)
      .def("__repr__", &Paving::str);

  m.SILLAGE_FN(leaf_paving, py::arg("box"), py::arg("tag"));
  m.SILLAGE_FN(join_pavings, py::arg("box"), py::arg("left"), py::arg("right"));
  m.SILLAGE_FN(graft_pavings, py::arg("top"), py::arg("leaves"), py::arg("pieces"), nogil);

  py::class_<SiviaOptions>(m, "SiviaOptions", DOC(SiviaOptions))
      .def(py::init([](bool parallel, const Budget* budget) {
             SiviaOptions o;
             o.parallel = parallel;
             if (budget) o.budget = *budget;
             return o;
           }),
           py::arg("parallel") = true, py::arg("budget") = nullptr,
           "Options: parallel (oneTBB tasks, default True) and a Budget (default: 10^7 boxes, 1 GiB).")
      .SILLAGE_FIELDS(SiviaOptions, parallel, budget)
      .def("__repr__", [](const SiviaOptions& o) {
        return std::string("SiviaOptions(parallel=") + (o.parallel ? "True" : "False") +
               ", budget=" + py::repr(py::cast(o.budget)).cast<std::string>() + ")";
      });
  py::class_<SiviaResult>(m, "SiviaResult", DOC(SiviaResult))
      .SILLAGE_READONLY_FIELDS(SiviaResult, paving, summary)
      .def("take", [](const SiviaResult& r) { return SiviaResult(r).take(); }, DOC(SiviaResult, take))
      .def("__iter__",
           [](const py::object& self) {
             return py::iter(py::make_tuple(self.attr("paving"), self.attr("summary")));
           },
           "paving, summary = result")
      .def("__repr__", [](const SiviaResult& r) {
        return "SiviaResult(paving=" + r.paving.str() + ", summary=" + r.summary.str() + ")";
      });

  // Every overload takes options=SiviaOptions() last, as in C++. Calls with a
  // Python callable always run sequentially (they need the GIL), whatever options.parallel.
  const auto opts = [] { return py::arg("options") = SiviaOptions{}; };

  // ---- sivia: Function first, so that a Function never goes to the callable overload ----
  def_sivia(
      m, "sivia", "sivia_run",
      +[](const IntervalVector& x0, const Function& f, const IntervalVector& y, double eps,
         const SiviaOptions& o) -> SiviaResult {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia_run(x0, f, y, eps, io); });
      },
      "SIVIA (thesis Alg. 1): paving of x0 for X = f^-1(Y).", DOC(sivia_run),
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("eps"), opts());
  def_sivia(
      m, "sivia", "sivia_run",
      +[](const IntervalVector& x0, const Function& f, const Interval& y, double eps,
         const SiviaOptions& o) -> SiviaResult {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia_run(x0, f, y, eps, io); });
      },
      DOC(sivia, IntervalVector_Function_Interval_double_SiviaOptions), DOC(sivia_run),
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("eps"), opts());
  def_sivia(
      m, "sivia", "sivia_run",
      +[](const IntervalVector& x0, const Function& f, const IntervalVector& y, const Ctc& ctc, double eps,
         const SiviaOptions& o) -> SiviaResult {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia_run(x0, f, y, ctc, eps, io); });
      },
      DOC(sivia, IntervalVector_Function_IntervalVector_Ctc_double_SiviaOptions), DOC(sivia_run),
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("ctc"), py::arg("eps"), opts());
  def_sivia(
      m, "sivia", "sivia_run",
      +[](const IntervalVector& x0, const Function& f, const Interval& y, const Ctc& ctc, double eps,
         const SiviaOptions& o) -> SiviaResult {
        return interruptible(
            o, [&](const SiviaOptions& io) { return sivia_run(x0, f, IntervalVector{y}, ctc, eps, io); });
      },
      DOC(sivia), DOC(sivia_run),
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("ctc"), py::arg("eps"), opts());
  def_sivia(
      m, "sivia", "sivia_run",
      +[](const IntervalVector& x0, const py::function& f, const IntervalVector& y, double eps,
         const SiviaOptions& o) -> SiviaResult {
        return sivia_run(x0, [&f](const IntervalVector& x) { return call_box_function(f, x); }, y, eps, sequential(o));
      },
      "SIVIA with a Python inclusion function f(box) -> box (or Interval); always sequential.", DOC(sivia_run),
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("eps"), opts());
  def_sivia(
      m, "sivia", "sivia_run",
      +[](const IntervalVector& x0, const py::function& f, const Interval& y, double eps,
         const SiviaOptions& o) -> SiviaResult {
        return sivia_run(x0, [&f](const IntervalVector& x) { return call_box_function(f, x); }, y, eps, sequential(o));
      },
      "SIVIA with a Python inclusion function f(box) -> Interval for X = f^-1([y]); always sequential.", DOC(sivia_run),
      py::arg("x0"), py::arg("f"), py::arg("y"), py::arg("eps"), opts());
  def_sivia(
      m, "sivia", "sivia_run",
      +[](const IntervalVector& x0, const Sep& sep, double eps, const SiviaOptions& o) -> SiviaResult {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia_run(x0, sep, eps, io); });
      },
      DOC(sivia, IntervalVector_Sep_double_SiviaOptions), DOC(sivia_run),
      py::arg("x0"), py::arg("sep"), py::arg("eps"), opts());
  def_sivia(
      m, "sivia", "sivia_run",
      +[](const IntervalVector& x0, const Ctc& ctc, double eps, const SiviaOptions& o) -> SiviaResult {
        return interruptible(o, [&](const SiviaOptions& io) { return sivia_run(x0, ctc, eps, io); });
      },
      DOC(sivia, IntervalVector_Ctc_double_SiviaOptions), DOC(sivia_run),
      py::arg("x0"), py::arg("ctc"), py::arg("eps"), opts());

  def_sivia(
      m, "kernel_sivia", "kernel_sivia_run",
      +[](const IntervalVector& x0, const Function& f_lo, const Function& f_hi, double eps,
         const SiviaOptions& o) -> SiviaResult {
        return interruptible(o, [&](const SiviaOptions& io) { return kernel_sivia_run(x0, f_lo, f_hi, eps, io); });
      },
      DOC(kernel_sivia, IntervalVector_Function_Function_double_SiviaOptions), DOC(kernel_sivia_run),
      py::arg("x0"), py::arg("f_lo"), py::arg("f_hi"), py::arg("eps"), opts());
  def_sivia(
      m, "kernel_sivia", "kernel_sivia_run",
      +[](const IntervalVector& x0, const py::function& f, double eps, const SiviaOptions& o) -> SiviaResult {
        auto bounds = [&f](const IntervalVector& x) {
          const py::object r = f(x);
          if (!py::isinstance<py::tuple>(r) && !py::isinstance<py::list>(r)) {
            throw ArgumentTypeError("kernel_sivia: f must return a pair ([f-]([x]), [f+]([x])), got " + type_name(r));
          }
          const auto t = r.cast<py::sequence>();
          if (t.size() != 2) throw Error("kernel_sivia: f must return a pair ([f-]([x]), [f+]([x]))");
          return std::pair{as_box(t[0], "kernel_sivia: f"), as_box(t[1], "kernel_sivia: f")};
        };
        return kernel_sivia_run(x0, bounds, eps, sequential(o));
      },
      "Kernel SIVIA with a Python f(box) -> (lower, upper) enclosures of the bound functions; always sequential.",
      DOC(kernel_sivia_run),
      py::arg("x0"), py::arg("f"), py::arg("eps"), opts());
}

}  // namespace sillage::python
