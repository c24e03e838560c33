// Python bindings of the tube layer: Trajectory, Tube (arithmetic,
// elementary functions as module-level overloads, numpy export), TubeVector
// (components are live references), builders and serialization.
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "arg_checks.h"
#include "bindings.h"
#include "docstrings.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/trajectory_arithmetic.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_builders.h"
#include "sillage/tube/tube_io.h"
#include "sillage/tube/tube_vector.h"
#include "sillage/tube/tube_vector_arithmetic.h"

namespace sillage::python {

namespace {

using TD = std::shared_ptr<TDomain>;

// (n, 2) array of bounds; an empty interval gives (inf, -inf) like IntervalVector.to_numpy.
py::array_t<double> bounds_array(std::span<const Interval> xs) {
  py::array_t<double> a({static_cast<py::ssize_t>(xs.size()), py::ssize_t{2}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const auto i = static_cast<py::ssize_t>(k);
    r(i, 0) = xs[k].is_empty() ? rounding::kInf : xs[k].lb();
    r(i, 1) = xs[k].is_empty() ? -rounding::kInf : xs[k].ub();
  }
  return a;
}

// One row [lb, ub] of a bounds array; (inf, -inf) is the empty interval (what
// slices_array gives for an empty slice). NaN, lb > ub or an infinite point are errors.
Interval interval_from_row(double lo, double hi, const std::string& where) {
  if (std::isnan(lo) || std::isnan(hi)) throw Error(where + " has a NaN bound");
  if (lo == rounding::kInf && hi == -rounding::kInf) return Interval::empty();
  if (lo > hi) {
    throw Error(where + ": lb > ub ([" + std::to_string(lo) + ", " + std::to_string(hi) +
                "]; an empty interval is written [inf, -inf])");
  }
  if (lo == rounding::kInf || hi == -rounding::kInf) throw Error(where + ": an infinite point is not an interval");
  return Interval(lo, hi);
}

// An (n, 2) array of bounds as n intervals (DimensionError if the shape is not (n, 2)).
std::vector<Interval> intervals_from_array(const py::handle& h, std::size_t n, const char* where, const char* what) {
  const Bounds a = bounds_of(h, where, what);
  if (a.ndim() != 2 || a.shape(0) != static_cast<py::ssize_t>(n) || a.shape(1) != 2) {
    throw DimensionError(std::string(where) + ": " + what + " must have shape (" + std::to_string(n) +
                         ", 2), got " + shape_text(a));
  }
  auto r = a.unchecked<2>();
  std::vector<Interval> xs;
  xs.reserve(n);
  for (py::ssize_t k = 0; k < r.shape(0); ++k) {
    xs.push_back(interval_from_row(r(k, 0), r(k, 1),
                                   std::string(where) + ": " + what + " row " + std::to_string(k)));
  }
  return xs;
}

// A (dim, n, 2) array (or a list of dim (n, 2) arrays) as dim lists of n intervals.
std::vector<std::vector<Interval>> components_from_array(const py::handle& h, std::size_t n, const char* where,
                                                         const char* what) {
  std::vector<std::vector<Interval>> cs;
  if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)) {
    std::size_t i = 0;
    for (const auto& item : h) {
      const std::string w = std::string(what) + "[" + std::to_string(i++) + "]";
      cs.push_back(intervals_from_array(item, n, where, w.c_str()));
    }
  } else {
    const Bounds a = bounds_of(h, where, what);
    if (a.ndim() != 3 || a.shape(0) < 1 || a.shape(1) != static_cast<py::ssize_t>(n) || a.shape(2) != 2) {
      throw DimensionError(std::string(where) + ": " + what + " must have shape (dim, " + std::to_string(n) +
                           ", 2) with dim >= 1, got " + shape_text(a));
    }
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
      const std::string w = std::string(what) + "[" + std::to_string(i) + "]";
      cs.push_back(intervals_from_array(a[py::make_tuple(i)], n, where, w.c_str()));
    }
  }
  if (cs.empty()) throw DimensionError(std::string(where) + ": " + what + " has no component");
  return cs;
}

// A tube with exactly these slices and gates (no consistency check: used to
// restore a pickled tube bit for bit). Their sizes are the TDomain's (the
// callers read them with intervals_from_array).
Tube tube_with(const TD& td, const std::vector<Interval>& slices, const std::vector<Interval>& gates) {
  Tube x(td);
  const Tube::Writer w = x.write();
  std::copy(slices.begin(), slices.end(), w.slices().begin());
  std::copy(gates.begin(), gates.end(), w.gates().begin());
  return x;
}

// (dim, n, 2) array of the slices (or gates) of every component.
py::array_t<double> components_array(const TubeVector& v, bool gates) {
  const std::size_t n = gates ? v.nb_slices() + 1 : v.nb_slices();
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(n), py::ssize_t{2}});
  auto r = a.mutable_unchecked<3>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto xs = gates ? v[i].gates() : v[i].slices();
    for (std::size_t k = 0; k < n; ++k) {
      const auto ii = static_cast<py::ssize_t>(i), kk = static_cast<py::ssize_t>(k);
      r(ii, kk, 0) = xs[k].is_empty() ? rounding::kInf : xs[k].lb();
      r(ii, kk, 1) = xs[k].is_empty() ? -rounding::kInf : xs[k].ub();
    }
  }
  return a;
}

// Slice-wise lb (what = 0), ub (1) or diam (2) of a tube, shape (N,).
py::array_t<double> slice_values(const Tube& x, int what) {
  py::array_t<double> a(static_cast<py::ssize_t>(x.nb_slices()));
  auto r = a.mutable_unchecked<1>();
  const auto xs = x.slices();
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const Interval& y = xs[k];
    const auto i = static_cast<py::ssize_t>(k);
    if (what == 0) r(i) = y.is_empty() ? rounding::kInf : y.lb();
    else if (what == 1) r(i) = y.is_empty() ? -rounding::kInf : y.ub();
    else r(i) = y.diam();
  }
  return a;
}

py::array_t<double> component_values(const TubeVector& v, int what) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(v.nb_slices())});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto row = slice_values(v[i], what);
    auto c = row.unchecked<1>();
    for (py::ssize_t k = 0; k < c.shape(0); ++k) r(static_cast<py::ssize_t>(i), k) = c(k);
  }
  return a;
}

// Every slice and gate inflated by r (r >= 0, finite or inf; Error otherwise).
Tube inflated(const Tube& x, double r) {
  if (!(r >= 0.0)) throw Error("Tube.inflate: the radius must be >= 0, got " + std::to_string(r));
  Tube y(x);
  {
    const Tube::Writer w = y.write();
    for (auto& s : w.slices()) s = s.inflate(r);
    for (auto& g : w.gates()) g = g.inflate(r);
  }
  return y;
}

// x + [-1, 1]·r, slice- and gate-wise: inflation by a tube of radii (its upper bounds count).
Tube inflated(const Tube& x, const Tube& r) {
  if (r.codomain().lb() < 0.0) throw Error("Tube.inflate: the radius tube has negative values");
  return x + Interval(-1.0, 1.0) * r;
}

// The index of the gate at time t, sampling the TDomain at t if t is not a time point yet.
std::size_t gate_at(const Tube& x, double t, const char* where) {
  if (std::isnan(t)) throw Error(std::string(where) + ": t is NaN");
  const auto& td = x.tdomain();
  const std::ptrdiff_t k = td->time_index(t);
  return k >= 0 ? static_cast<std::size_t>(k) : td->sample(t);
}

const char* const kTubeSetDoc =
    "set(y): every slice and gate := y.\n"
    "set(y, k): slice k := y (an index), its two gates := y & the neighbouring slice (an end gate := y).\n"
    "set(y, t=t): the value at time t := y, i.e. the gate at t (like Codac's set(y, t)). If t is not a\n"
    "time point yet, the TDomain is sampled at t first (td.sample(t)), which splits the slice containing t\n"
    "in every tube on that TDomain (their values do not change). The slices are not changed (see\n"
    "set_gate). Error if t is NaN or outside the domain, or if both k and t are given.";

// Python str of an interval vector: ([a, b], [c, d]).
std::string box_text(const IntervalVector& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i > 0) s += ", ";
    s += v[i].str();
  }
  return s + ")";
}

void init_tube_class(py::module_& m) {
  using T = Tube;
  py::class_<T, std::shared_ptr<T>> c(m, "Tube",
                                      DOC(Tube));
  def_copy(c);
  c.def(py::init([](TD td, const py::array& slices, const py::object& gates) {
          const std::size_t n = td->nb_slices();
          if (slices.ndim() == 1 && gates.is_none()) {  // (N,) points: degenerate slices, as IntervalVector
            const auto points = py::module_::import("sillage._sillage").attr("IntervalVector")(slices);
            return T(td, points.cast<IntervalVector>().components());
          }
          auto s = intervals_from_array(slices, n, "Tube(tdomain, slices)", "slices");
          if (gates.is_none()) return T(td, s);
          return T(td, s, intervals_from_array(gates, n + 1, "Tube(tdomain, slices, gates)", "gates"));
        }),
        py::arg("tdomain"), py::arg("slices").noconvert(), py::arg("gates") = py::none(),
        "From numpy arrays of bounds: slices of shape (N, 2), row k = [lb, ub] of slice k (an (N,) array:\n"
        "points, degenerate slices); gates (optional) of shape (N+1, 2). Without gates, gate k is the\n"
        "intersection of the two slices around t_k and the end gates are the end slices. [inf, -inf] is\n"
        "the empty interval (what slices_array() gives).\n"
        "DimensionError for a wrong shape; sillage.Error for NaN or lb > ub. A gate disjoint from a\n"
        "neighbouring slice is kept: that tube holds no trajectory, which a network reports as empty.")
      .def(py::init<TD, const std::string&>(), py::arg("tdomain"), py::arg("expr"),
           DOC(Tube, Tube, TDomain_string))
      .def(py::init<TD, const Function&>(), py::arg("tdomain"), py::arg("f"),
           DOC(Tube, Tube, TDomain_Function))
      .def(py::init<TD, const Interval&>(), py::arg("tdomain"), py::arg("x") = Interval(),
           DOC(Tube, Tube, TDomain_Interval))
      .def(py::init<TD, const std::vector<Interval>&>(), py::arg("tdomain"), py::arg("slices"),
           DOC(Tube, Tube, TDomain_vector_Interval))
      .def(py::init<TD, const std::vector<Interval>&, const std::vector<Interval>&>(), py::arg("tdomain"),
           py::arg("slices"), py::arg("gates"), DOC(Tube, Tube, TDomain_vector_Interval_vector_Interval))
      .SILLAGE_DEFS(Tube, tdomain, nb_slices, is_angle)
      .SILLAGE_DEF(Tube, set_angle, py::arg("on"))
      // Signed indices: -1 is an OutOfRangeError, not an argument mismatch.
      .def("slice", [](const T& x, py::ssize_t k) { return x.slice(index_arg(k, "Tube.slice", "slice")); },
           py::arg("k"), "[x](k), the codomain of slice k (0 <= k < N).")
      .def("gate", [](const T& x, py::ssize_t k) { return x.gate(index_arg(k, "Tube.gate", "gate")); }, py::arg("k"),
           "[x](t_k), gate k (0 <= k <= N).")
      .def(
          "set",
          [](T& x, const Interval& y, const py::object& k, const py::object& t) {
            if (!k.is_none() && !t.is_none()) throw Error("Tube.set: give a slice index k or a time t, not both");
            if (!t.is_none()) {
              const std::size_t g = gate_at(x, t.cast<double>(), "Tube.set(y, t=t)");
              x.set_gate(g, y);
            } else if (!k.is_none()) {
              x.set(y, index_arg(k.cast<py::ssize_t>(), "Tube.set(y, k)", "slice"));
            } else {
              x.set(y);
            }
          },
          py::arg("y"), py::arg("k") = py::none(), py::kw_only(), py::arg("t") = py::none(), kTubeSetDoc)
      .def(
          "set_gate",
          [](T& x, py::ssize_t k, const Interval& y) { x.set_gate(index_arg(k, "Tube.set_gate", "gate"), y); },
          py::arg("k"), py::arg("y"), "Gate k := y (not checked against the slices).")
      .SILLAGE_DEFS(Tube, codomain, volume)
      .def("thickness", [](const T& x, py::ssize_t k) { return x.thickness(index_arg(k, "Tube.thickness", "slice")); },
           py::arg("k"), DOC(Tube, thickness))
      .SILLAGE_DEFS(Tube, max_thickness, is_empty)
      .SILLAGE_DEF(Tube, is_subset, py::arg("y"))
      .SILLAGE_DEF(Tube, contains, py::arg("trajectory"))
      .def("__call__", py::overload_cast<double>(&T::operator(), py::const_), py::arg("t"),
           DOC(Tube, op_call, double))
      .def("__call__", py::overload_cast<const Interval&>(&T::operator(), py::const_), py::arg("t"))
      .def("lb", [](const T& x) { return slice_values(x, 0); },
           "numpy array (N,) of the slice lower bounds (inf for an empty slice); gates: gates_array()[:, 0].")
      .def("ub", [](const T& x) { return slice_values(x, 1); },
           "numpy array (N,) of the slice upper bounds (-inf for an empty slice); gates: gates_array()[:, 1].")
      .def("diam", [](const T& x) { return slice_values(x, 2); },
           "numpy array (N,) of the slice diameters, rounded up (NaN for an empty slice, like Interval.diam).")
      .def("inflate", py::overload_cast<const T&, double>(&inflated), py::arg("r"),
           "A new tube: every slice and gate inflated by r >= 0 (this tube is unchanged, like Interval.inflate).")
      .def("inflate", py::overload_cast<const T&, const T&>(&inflated), py::arg("r"),
           "A new tube: self + [-1, 1]·r slice- and gate-wise, r a tube of radii >= 0 on the same TDomain.")
      .def("inverse", py::overload_cast<const Interval&>(&T::inverse, py::const_), py::arg("y"),
           DOC(Tube, inverse, Interval))
      .def("inverse_components",
           [](const T& x, const Interval& y) {
             std::vector<Interval> cs;
             x.inverse(y, cs);
             return cs;
           },
           py::arg("y"), "The connected subsets of the inverse, in time order.")
      .def("slices_array", [](const T& x) { return bounds_array(x.slices()); },
           "(N, 2) numpy array of slice bounds (an empty slice gives [inf, -inf]); Tube(td, a) takes it back.")
      .def("gates_array", [](const T& x) { return bounds_array(x.gates()); },
           "(N+1, 2) numpy array of gate bounds (an empty gate gives [inf, -inf]).")
      .def("__repr__",
           [](const T& x) {
             return "Tube(t=" + x.tdomain()->t0_tf().str() + ", " + std::to_string(x.nb_slices()) +
                    " slices, codomain=" + x.codomain().str() + ")";
           })
      // (tdomain, slices, gates): restored bit for bit, on the same TDomain object as its companions.
      .def(py::pickle(
          [](const T& x) { return py::make_tuple(x.tdomain(), bounds_array(x.slices()), bounds_array(x.gates())); },
          [](const py::tuple& st) {
            TD td = st[0].cast<TD>();
            const std::size_t n = td->nb_slices();
            return tube_with(td, intervals_from_array(st[1], n, "Tube.__setstate__", "slices"),
                             intervals_from_array(st[2], n + 1, "Tube.__setstate__", "gates"));
          }))
      .def(py::self == py::self)
      .def(py::self != py::self)
      .def(-py::self)
      .def("__abs__", [](const T& x) { return abs(x); })
      .def("__pow__", [](const T& x, int n) { return pow(x, n); }, py::is_operator())
      .def("__pow__", [](const T& x, double p) { return pow(x, p); }, py::is_operator())
      .def("__pow__", [](const T& x, const Interval& p) { return pow(x, p); }, py::is_operator());
  c.attr("__hash__") = py::none();
  c.attr("__array_ufunc__") = py::none();

  // With a Tube or an Interval (or a float) on either side; in-place forms modify self (and
  // give the same Python object back).
#define SILLAGE_TUBE_BIN(op)                                                                             \
  c.def(py::self op py::self).def(py::self op Interval()).def(Interval() op py::self);                   \
  c.def(py::self op## = py::self).def(py::self op## = Interval());
  SILLAGE_TUBE_BIN(+)
  SILLAGE_TUBE_BIN(-)
  SILLAGE_TUBE_BIN(*)
  SILLAGE_TUBE_BIN(/)
#undef SILLAGE_TUBE_BIN
  c.def(py::self & py::self).def(py::self | py::self).def(py::self &= py::self).def(py::self |= py::self);
}

void init_tube_functions(py::module_& m) {
  using T = Tube;
  using F1 = T (*)(const T&);
  // Overloads chain onto the Interval ones defined by init_interval.
  m.def("sqr", static_cast<F1>(&sqr), py::arg("x"), "sqr of a tube, slice- and gate-wise (rigorous).");
  m.def("sqrt", static_cast<F1>(&sqrt), py::arg("x"), DOC(sqrt, Tube));
  m.def("exp", static_cast<F1>(&exp), py::arg("x"), DOC(exp, Tube));
  m.def("log", static_cast<F1>(&log), py::arg("x"), DOC(log, Tube));
  m.def("sin", static_cast<F1>(&sin), py::arg("x"), DOC(sin, Tube));
  m.def("cos", static_cast<F1>(&cos), py::arg("x"), DOC(cos, Tube));
  m.def("tan", static_cast<F1>(&tan), py::arg("x"), DOC(tan, Tube));
  m.def("asin", static_cast<F1>(&asin), py::arg("x"), DOC(asin, Tube));
  m.def("acos", static_cast<F1>(&acos), py::arg("x"), DOC(acos, Tube));
  m.def("atan", static_cast<F1>(&atan), py::arg("x"), DOC(atan, Tube));
  m.def("sinh", static_cast<F1>(&sinh), py::arg("x"), DOC(sinh, Tube));
  m.def("cosh", static_cast<F1>(&cosh), py::arg("x"), DOC(cosh, Tube));
  m.def("tanh", static_cast<F1>(&tanh), py::arg("x"), DOC(tanh, Tube));
  m.def("abs", static_cast<F1>(&abs), py::arg("x"), DOC(abs, Tube));
  m.def("sign", static_cast<F1>(&sign), py::arg("x"), DOC(sign, Tube));
  m.def("pow", static_cast<T (*)(const T&, int)>(&pow), py::arg("x"), py::arg("n"),
        DOC(pow, Tube_int));
  m.def("pow", static_cast<T (*)(const T&, double)>(&pow), py::arg("x"), py::arg("p"),
        DOC(pow, Tube_double));
  m.def("pow", static_cast<T (*)(const T&, const Interval&)>(&pow), py::arg("x"), py::arg("p"),
        DOC(pow, Tube_Interval));
  m.def("pow", static_cast<T (*)(const T&, const T&)>(&pow), py::arg("x"), py::arg("p"),
        DOC(pow, Tube_Tube));
  m.def("root", static_cast<T (*)(const T&, int)>(&root), py::arg("x"), py::arg("n"),
        DOC(root, Tube_int));
  m.def("atan2", static_cast<T (*)(const T&, const T&)>(&atan2), py::arg("y"), py::arg("x"),
        DOC(atan2, Tube_Tube));
  m.def("atan2", static_cast<T (*)(const T&, const Interval&)>(&atan2), py::arg("y"), py::arg("x"),
        DOC(atan2, Tube_Interval));
  m.def("atan2", static_cast<T (*)(const Interval&, const T&)>(&atan2), py::arg("y"), py::arg("x"),
        DOC(atan2, Interval_Tube));
  m.def("min", static_cast<T (*)(const T&, const T&)>(&min), py::arg("x"), py::arg("y"),
        DOC(min, Tube_Tube));
  m.def("max", static_cast<T (*)(const T&, const T&)>(&max), py::arg("x"), py::arg("y"),
        DOC(max, Tube_Tube));
  m.def("hull", [](const T& x, const T& y) { return x | y; }, py::arg("x"), py::arg("y"),
        DOC(hull));

  m.def("tube_from_data", py::overload_cast<TD, const Trajectory&, double>(&tube_from_data), py::arg("tdomain"),
        py::arg("data"), py::arg("error") = 0.0, DOC(tube_from_data, TDomain_Trajectory_double));
  m.def("tube_from_data", py::overload_cast<TD, const Trajectory&, double, const Interval&>(&tube_from_data),
        py::arg("tdomain"), py::arg("data"), py::arg("error"), py::arg("dx"),
        DOC(tube_from_data, TDomain_Trajectory_double_Interval));
  m.SILLAGE_FN(tube_from_bounds, py::arg("tdomain"), py::arg("lb"), py::arg("ub"));
  m.def("save_tube", py::overload_cast<const T&, const std::string&>(&save), py::arg("x"), py::arg("path"),
        "Writes a Tube or a TubeVector (with its time points) to a file.");
  m.def("save_tube", py::overload_cast<const TubeVector&, const std::string&>(&save), py::arg("x"),
        py::arg("path"), "Writes a TubeVector (with its time points) to a file; read it with load_tube_vector.");
  m.def("load_tube", py::overload_cast<const std::string&, TD>(&load_tube), py::arg("path"),
        py::arg("tdomain") = TD(), DOC(load_tube, string_TDomain));
  m.def("load_tube_vector", py::overload_cast<const std::string&, TD>(&load_tube_vector), py::arg("path"),
        py::arg("tdomain") = TD(), DOC(load_tube_vector, string_TDomain));
}

void init_tube_vector(py::module_& m) {
  using V = TubeVector;
  py::class_<V, std::shared_ptr<V>> c(m, "TubeVector", DOC(TubeVector));
  def_copy(c);
  const auto from_arrays = [](TD td, const py::handle& slices, const py::object& gates) {
    const std::size_t n = td->nb_slices();
    const auto s = components_from_array(slices, n, "TubeVector(tdomain, slices)", "slices");
    std::vector<std::vector<Interval>> g;
    if (!gates.is_none()) {
      g = components_from_array(gates, n + 1, "TubeVector(tdomain, slices, gates)", "gates");
      check_same_size(s.size(), g.size(), "TubeVector(tdomain, slices, gates)");
    }
    return componentwise(s.size(), [&](std::size_t i) { return g.empty() ? Tube(td, s[i]) : Tube(td, s[i], g[i]); });
  };
  constexpr const char* kArraysDoc =
      "From numpy bounds: slices of shape (dim, N, 2) or a list of dim (N, 2) arrays, component i as in\n"
      "Tube(td, slices[i]); gates (optional) of shape (dim, N+1, 2) or a list of (N+1, 2) arrays.\n"
      "A 2-D array (n, 2) is a box: constant components, as TubeVector(td, IntervalVector(a)).";
  c.def(py::init([from_arrays](TD td, const py::array& slices, const py::object& gates) {
          if (slices.ndim() == 2 && gates.is_none()) {
            return V(td, py::module_::import("sillage._sillage").attr("IntervalVector")(slices).cast<IntervalVector>());
          }
          return from_arrays(td, slices, gates);
        }),
        py::arg("tdomain"), py::arg("slices").noconvert(), py::arg("gates") = py::none(), kArraysDoc)
      .def(py::init<TD, const std::string&>(), py::arg("tdomain"), py::arg("expr"),
           DOC(TubeVector, TubeVector, TDomain_string))
      .def(py::init<TD, const Function&>(), py::arg("tdomain"), py::arg("f"), DOC(TubeVector, TubeVector, TDomain_Function))
      .def(py::init<TD, std::size_t, const Interval&>(), py::arg("tdomain"), py::arg("n"), py::arg("x") = Interval(),
           DOC(TubeVector, TubeVector, TDomain_size_t_Interval))
      .def(py::init<TD, const IntervalVector&>(), py::arg("tdomain"), py::arg("x"),
           DOC(TubeVector, TubeVector, TDomain_IntervalVector))
      // Registered after the box form: a list of ndarrays is taken here (no conversion needed), a list
      // of [lb, ub] pairs by IntervalVector.
      .def(py::init([from_arrays](TD td, const std::vector<py::array>& slices, const py::object& gates) {
             return from_arrays(td, py::cast(slices), gates);
           }),
           py::arg("tdomain"), py::arg("slices").noconvert(), py::arg("gates") = py::none(), kArraysDoc)
      .def(py::init<std::vector<Tube>>(), py::arg("tubes"), DOC(TubeVector, TubeVector, vector_Tube))
      .SILLAGE_DEF(TubeVector, size)
      .def("__len__", &V::size)
      .SILLAGE_DEFS(TubeVector, tdomain, nb_slices)
      // The component itself (a heap object of its own, shared): a live
      // reference that stays valid whatever happens to the vector, and that
      // ContractorNetwork identifies with the component of DomainRef.component.
      .def("__getitem__", [](V& v, long long i) { return v.shared_component(py_index(i, v.size(), "TubeVector")); },
           py::arg("i"), DOC(TubeVector, op_index))
      .def("__setitem__",
           [](V& v, long long i, const Tube& x) {
             Tube& xi = v[py_index(i, v.size(), "TubeVector")];
             if (x.tdomain() != xi.tdomain()) throw DimensionError("TubeVector[i] = x: x is on another TDomain");
             xi = x;
           },
           py::arg("i"), py::arg("x"), "Component i := a copy of the tube x (same TDomain).")
      .SILLAGE_DEF(TubeVector, subvector, py::arg("i"), py::arg("j"))
      .def("slice", [](const V& v, py::ssize_t k) { return v.slice(index_arg(k, "TubeVector.slice", "slice")); },
           py::arg("k"), DOC(TubeVector, slice))
      .def("gate", [](const V& v, py::ssize_t k) { return v.gate(index_arg(k, "TubeVector.gate", "gate")); },
           py::arg("k"), DOC(TubeVector, gate))
      .def("__call__", py::overload_cast<double>(&V::operator(), py::const_), py::arg("t"),
           DOC(TubeVector, op_call, double))
      .def("__call__", py::overload_cast<const Interval&>(&V::operator(), py::const_), py::arg("t"))
      .SILLAGE_DEFS(TubeVector, codomain, volume, max_thickness, is_empty)
      .SILLAGE_DEF(TubeVector, is_subset, py::arg("y"))
      .SILLAGE_DEF(TubeVector, contains, py::arg("trajectories"))
      .def("contains", [](const V& x, const TrajectoryVector& y) { return x.contains(y.components()); },
           py::arg("trajectory"), DOC(TubeVector, contains))
      .def("slices_array", [](const V& v) { return components_array(v, false); },
           "(dim, N, 2) numpy array of slice bounds ([inf, -inf] for empty); TubeVector(td, a) takes it back.")
      .def("gates_array", [](const V& v) { return components_array(v, true); },
           "(dim, N+1, 2) numpy array of gate bounds ([inf, -inf] for empty).")
      .def("lb", [](const V& v) { return component_values(v, 0); },
           "(dim, N) numpy array of slice lower bounds (row i = self[i].lb()).")
      .def("ub", [](const V& v) { return component_values(v, 1); },
           "(dim, N) numpy array of slice upper bounds (row i = self[i].ub()).")
      .def("diam", [](const V& v) { return component_values(v, 2); },
           "(dim, N) numpy array of slice diameters (row i = self[i].diam()).")
      .def("inflate",
           [](const V& v, double r) {
             return componentwise(v.size(), [&](std::size_t i) { return inflated(v[i], r); });
           },
           py::arg("r"), "A new tube vector: every component inflated by r >= 0 (see Tube.inflate).")
      .def("inflate",
           [](const V& v, const IntervalVector& r) {
             check_same_size(v.size(), r.size(), "TubeVector.inflate");
             return componentwise(v.size(), [&](std::size_t i) {
               if (r[i].is_empty()) throw Error("TubeVector.inflate: radius " + std::to_string(i) + " is empty");
               return inflated(v[i], r[i].ub());
             });
           },
           py::arg("r"), "Component i inflated by r[i] (the upper bound of each component of r, >= 0).")
      .def("inflate",
           [](const V& v, const V& r) {
             check_same_size(v.size(), r.size(), "TubeVector.inflate");
             return componentwise(v.size(), [&](std::size_t i) { return inflated(v[i], r[i]); });
           },
           py::arg("r"), "Component i inflated by the tube of radii r[i] (see Tube.inflate).")
      .def("inverse", [](const V& x, const IntervalVector& y) { return inverse(x, y); }, py::arg("y"),
           "Hull of the times where the box [x](t) meets the box y (all components at once); empty if none.")
      .def(
          "set",
          [](V& x, const IntervalVector& y, const py::object& k, const py::object& t) {
            if (!k.is_none() && !t.is_none()) throw Error("TubeVector.set: give a slice index k or a time t, not both");
            if (!t.is_none()) {
              x.set_gate(gate_at(x[0], t.cast<double>(), "TubeVector.set(y, t=t)"), y);
            } else if (!k.is_none()) {
              x.set(y, index_arg(k.cast<py::ssize_t>(), "TubeVector.set(y, k)", "slice"));
            } else {
              x.set(y);
            }
          },
          py::arg("y"), py::arg("k") = py::none(), py::kw_only(), py::arg("t") = py::none(),
          "Tube.set component-wise with a box y: set(y), set(y, k) (slice index), set(y, t=t) (the gate at\n"
          "time t, sampling the TDomain at t if needed).")
      .def(
          "set_gate",
          [](V& v, py::ssize_t k, const IntervalVector& y) { v.set_gate(index_arg(k, "TubeVector.set_gate", "gate"), y); },
          py::arg("k"), py::arg("y"), DOC(TubeVector, set_gate))
      .def(py::self == py::self)
      .def(py::self != py::self)
      .def(py::self &= py::self)
      .def(py::self |= py::self)
      .def("__and__", [](const V& a, const V& b) { V r(a); return r &= b; }, py::is_operator())
      .def("__or__", [](const V& a, const V& b) { V r(a); return r |= b; }, py::is_operator())
      .def(-py::self)
      .def("__repr__",
           [](const V& v) {
             return "TubeVector(t=" + v.tdomain()->t0_tf().str() + ", " + std::to_string(v.nb_slices()) +
                    " slices, dim " + std::to_string(v.size()) + ", codomain=" + box_text(v.codomain()) + ")";
           })
      // (tdomain, slices, gates) as (dim, N, 2) / (dim, N+1, 2) arrays: bit-exact, TDomain shared.
      .def(py::pickle(
          [](const V& v) { return py::make_tuple(v.tdomain(), components_array(v, false), components_array(v, true)); },
          [](const py::tuple& st) {
            TD td = st[0].cast<TD>();
            const std::size_t n = td->nb_slices();
            const auto s = components_from_array(st[1], n, "TubeVector.__setstate__", "slices");
            const auto g = components_from_array(st[2], n + 1, "TubeVector.__setstate__", "gates");
            check_same_size(s.size(), g.size(), "TubeVector.__setstate__");
            return componentwise(s.size(), [&](std::size_t i) { return tube_with(td, s[i], g[i]); });
          }));
  c.attr("__hash__") = py::none();
  c.attr("__array_ufunc__") = py::none();

  // Component-wise arithmetic: with a TubeVector or a box (component i with component i), with a
  // Tube or an Interval/float (every component with it). DimensionError if sizes or TDomains differ.
#define SILLAGE_TV_BIN(name, rname, iname, op)                                                              \
  c.def(name, [](const V& a, const V& b) { return a op b; }, py::is_operator())                              \
      .def(name, [](const V& a, const Tube& b) { return a op b; }, py::is_operator())                       \
      .def(name, [](const V& a, const Interval& b) { return a op b; }, py::is_operator())                   \
      .def(name, [](const V& a, const IntervalVector& b) { return a op b; }, py::is_operator())             \
      .def(rname, [](const V& a, const Tube& b) { return b op a; }, py::is_operator())                      \
      .def(rname, [](const V& a, const Interval& b) { return b op a; }, py::is_operator())                  \
      .def(rname, [](const V& a, const IntervalVector& b) { return b op a; }, py::is_operator())            \
      .def(iname, [](const py::object& self, const py::object& b) {                                          \
        /* in place: the components keep their identity (live references stay valid) */                     \
        const V r = self.attr(name)(b).cast<V>();                                                             \
        V& a = self.cast<V&>();                                                                               \
        for (std::size_t i = 0; i < a.size(); ++i) a[i] = r[i];                                              \
        return self;                                                                                          \
      }, py::is_operator());
  SILLAGE_TV_BIN("__add__", "__radd__", "__iadd__", +)
  SILLAGE_TV_BIN("__sub__", "__rsub__", "__isub__", -)
  SILLAGE_TV_BIN("__mul__", "__rmul__", "__imul__", *)
  SILLAGE_TV_BIN("__truediv__", "__rtruediv__", "__itruediv__", /)
#undef SILLAGE_TV_BIN
}

}  // namespace

SILLAGE_BINDING(tube, "expr", "interval", "tdomain", "trajectory") {
  init_tube_class(m);
  init_tube_vector(m);    // before the functions, so their signatures name TubeVector
  init_tube_functions(m);
}

}  // namespace sillage::python
