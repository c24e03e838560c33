// Interval, IntervalVector, IntervalMatrix, the elementary functions and the
// backward projections.
//
// The classes are held by std::shared_ptr: a ContractorNetwork keeps the very
// Python objects it is given and contracts them in place, so in-place operators
// (&=, |=, +=, ...) modify the object itself. Indexing returns copies
// (v[i] &= y still works: Python writes the result back with __setitem__).
// The empty interval is stored as the bound pair (inf, -inf), which is also
// what to_numpy() gives and what the constructors accept back.
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "arg_checks.h"
#include "bindings.h"
#include "docstrings.h"
#include "sillage/interval/backward.h"
#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"
#include "sillage/interval/interval_matrix.h"
#include "sillage/interval/interval_vector.h"

namespace sillage::python {

bool is_int(const py::handle& h) {
  return PyLong_Check(h.ptr()) || (!PyFloat_Check(h.ptr()) && PyIndex_Check(h.ptr()));
}

// Past the largest double, up to inf.
Interval int_enclosure(const py::handle& h) {
  const auto n = py::reinterpret_steal<py::int_>(PyNumber_Index(h.ptr()));
  if (!n) throw py::error_already_set();
  const bool positive = PyObject_RichCompareBool(n.ptr(), py::int_(0).ptr(), Py_GT) == 1;
  const double d = PyLong_AsDouble(n.ptr());
  if (d == -1.0 && PyErr_Occurred()) {  // beyond the largest double
    PyErr_Clear();
    return positive ? Interval(rounding::kMax, rounding::kInf) : Interval(-rounding::kInf, -rounding::kMax);
  }
  const auto back = py::reinterpret_steal<py::int_>(PyLong_FromDouble(d));
  if (PyObject_RichCompareBool(n.ptr(), back.ptr(), Py_EQ) == 1) return Interval(d);
  if (PyObject_RichCompareBool(n.ptr(), back.ptr(), Py_LT) == 1) return Interval(rounding::next_down(d), d);
  return Interval(d, rounding::next_up(d));
}

namespace {

constexpr double kInf = rounding::kInf;
using FloatArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string type_name(const py::handle& h) { return py::str(py::type::handle_of(h).attr("__name__")); }

double as_double(const py::handle& h, const std::string& where) {
  const double v = PyFloat_AsDouble(h.ptr());
  if (v == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw Error(where + ": expected a number, got " + type_name(h));
  }
  return v;
}

// [lb, ub], the pair (inf, -inf) standing for the empty set.
Interval from_bounds(double lb, double ub) {
  if (lb == kInf && ub == -kInf) return Interval::empty();
  return Interval(lb, ub);
}

// A bound of [lb, ub]: a float as it is, an int rounded outward (lb down, ub up).
double bound(const py::handle& b, bool upper, const std::string& where) {
  if (!is_int(b)) return as_double(b, where);
  const Interval e = int_enclosure(b);
  return upper ? e.ub() : e.lb();
}

// Runs f, prefixing the message of a sillage::Error with `where`.
template <class F>
auto located(const std::string& where, F f) {
  try {
    return f();
  } catch (const Error& e) {
    throw Error(where + ": " + e.what());
  }
}

// An Interval, a number (degenerate interval) or a pair [lb, ub].
Interval to_interval(const py::handle& h, const std::string& where) {
  if (py::isinstance<Interval>(h)) return h.cast<Interval>();
  if (!py::isinstance<py::str>(h) && !py::isinstance<py::bytes>(h)) {
    if (is_int(h)) return int_enclosure(h);
    if (PyNumber_Check(h.ptr()) && !PySequence_Check(h.ptr())) {
      const double v = as_double(h, where);
      return located(where, [v] { return Interval(v); });
    }
    if (PySequence_Check(h.ptr())) {
      const auto s = py::reinterpret_borrow<py::sequence>(h);
      if (s.size() == 2) {
        const double lb = bound(s[0], false, where), ub = bound(s[1], true, where);
        return located(where, [=] { return from_bounds(lb, ub); });
      }
      throw DimensionError(where + ": a pair [lb, ub] has 2 bounds, got " + std::to_string(s.size()));
    }
  }
  throw Error(where + ": expected an Interval, a number or a pair [lb, ub], got " + type_name(h));
}

}  // namespace

bool is_ndarray(const py::handle& h) {
  // An array can only exist once numpy is imported; None there means "import numpy" is blocked.
  PyObject* numpy = PyDict_GetItemString(PyImport_GetModuleDict(), "numpy");
  if (numpy == nullptr || numpy == Py_None) return false;
  return py::isinstance<py::array>(h);
}

namespace {

IntervalVector vector_from(const py::handle& obj) {
  if (py::isinstance<IntervalVector>(obj)) return obj.cast<IntervalVector>();
  if (py::isinstance<py::int_>(obj)) {
    const long long n = obj.cast<long long>();
    if (n < 0) throw DimensionError("IntervalVector(n): n must be >= 0, got " + std::to_string(n));
    return IntervalVector(static_cast<std::size_t>(n));
  }
  if (is_ndarray(obj)) {
    const auto a = FloatArray::ensure(obj);
    if (!a) throw Error("IntervalVector: the array must hold numbers");
    if (a.ndim() == 1) {  // points
      IntervalVector v(static_cast<std::size_t>(a.shape(0)));
      for (py::ssize_t i = 0; i < a.shape(0); ++i)
        v[i] = located("IntervalVector: component " + std::to_string(i), [&] { return Interval(a.at(i)); });
      return v;
    }
    if (a.ndim() != 2 || a.shape(1) != 2) {
      throw DimensionError("IntervalVector: expected an (n, 2) array of bounds, got " + std::to_string(a.ndim()) +
                           " dimensions");
    }
    IntervalVector v(static_cast<std::size_t>(a.shape(0)));
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      v[i] = located("IntervalVector: component " + std::to_string(i),
                     [&] { return from_bounds(a.at(i, 0), a.at(i, 1)); });
    return v;
  }
  if (!py::isinstance<py::iterable>(obj) || py::isinstance<py::str>(obj)) {
    throw Error("IntervalVector: expected a size, a list of intervals or an (n, 2) array, got " + type_name(obj));
  }
  std::vector<Interval> xs;
  for (const auto& item : obj) xs.push_back(to_interval(item, "IntervalVector: component " + std::to_string(xs.size())));
  return IntervalVector(std::move(xs));
}

IntervalMatrix matrix_from(const py::handle& obj) {
  if (py::isinstance<IntervalMatrix>(obj)) return obj.cast<IntervalMatrix>();
  if (is_ndarray(obj)) {
    const auto a = FloatArray::ensure(obj);
    if (!a) throw Error("IntervalMatrix: the array must hold numbers");
    if (a.ndim() != 2 && !(a.ndim() == 3 && a.shape(2) == 2)) {
      throw DimensionError("IntervalMatrix: expected an (n, m, 2) array of bounds or an (n, m) array of points");
    }
    IntervalMatrix m(static_cast<std::size_t>(a.shape(0)), static_cast<std::size_t>(a.shape(1)));
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      for (py::ssize_t j = 0; j < a.shape(1); ++j)
        m(i, j) = located("IntervalMatrix: entry (" + std::to_string(i) + ", " + std::to_string(j) + ")", [&] {
          return a.ndim() == 2 ? Interval(a.at(i, j)) : from_bounds(a.at(i, j, 0), a.at(i, j, 1));
        });
    return m;
  }
  if (!py::isinstance<py::iterable>(obj) || py::isinstance<py::str>(obj)) {
    throw Error("IntervalMatrix: expected a list of rows or an (n, m, 2) array, got " + type_name(obj));
  }
  std::vector<IntervalVector> rows;
  for (const auto& r : obj)
    rows.push_back(located("IntervalMatrix: row " + std::to_string(rows.size()), [&] { return vector_from(r); }));
  return IntervalMatrix(rows);
}

py::array_t<double> vector_to_numpy(const IntervalVector& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{2}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    r(i, 0) = v[i].lb();
    r(i, 1) = v[i].ub();
  }
  return a;
}

py::array_t<double> matrix_to_numpy(const IntervalMatrix& m) {
  py::array_t<double> a({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols()), py::ssize_t{2}});
  auto r = a.mutable_unchecked<3>();
  for (std::size_t i = 0; i < m.rows(); ++i)
    for (std::size_t j = 0; j < m.cols(); ++j) {
      r(i, j, 0) = m(i, j).lb();
      r(i, j, 1) = m(i, j).ub();
    }
  return a;
}

py::object as_array(const py::array& a, const py::object& dtype) {
  return dtype.is_none() ? py::object(a) : a.attr("astype")(dtype);
}

py::tuple bounds_state(const Interval& x) { return py::make_tuple(x.lb(), x.ub()); }

void init_interval_class(py::module_& m) {
  using I = Interval;
  py::class_<I, std::shared_ptr<I>> c(m, "Interval",
                                      DOC(Interval));
  def_copy(c);
  // An int that is not a double is enclosed by its two neighbours
  // (Interval(2**53 + 1) = [2^53, 2^53 + 2]); in [lb, ub] lb rounds down, ub up.
  c.def(py::init<>(), "The whole real line.")
      .def(py::init([](const py::object& x) {
             if (py::isinstance<I>(x)) return x.cast<I>();
             if (!PyNumber_Check(x.ptr()) || PySequence_Check(x.ptr()))
               throw py::type_error("Interval(x): expected a number or an Interval, got " + type_name(x));
             return is_int(x) ? int_enclosure(x) : I(as_double(x, "Interval(x)"));
           }),
           py::arg("x"), "[x, x] for a float; for an int, the tightest interval around it; a copy of an Interval.")
      .def(py::init([](const py::object& lb, const py::object& ub) {
             for (const py::object& b : {lb, ub})
               if (!PyNumber_Check(b.ptr()) || PySequence_Check(b.ptr()))
                 throw py::type_error("Interval(lb, ub): expected numbers, got " + type_name(b));
             const double l = bound(lb, false, "Interval(lb, ub)"), u = bound(ub, true, "Interval(lb, ub)");
             return located("Interval(lb, ub)", [=] { return Interval(l, u); });
           }),
           py::arg("lb"), py::arg("ub"),
           "[lb, ub]; a float bound is taken as it is, an int bound rounded outward. Interval(inf, -inf) is the "
           "empty set; Error if lb > ub.")
      .def_static("empty", &I::empty, "The empty interval.")
      .def_static("all_reals", &I::all_reals, "The real line [-inf, inf].")
      .def_static("pos_reals", &I::pos_reals, "[0, inf].")
      .def_static("neg_reals", &I::neg_reals, "[-inf, 0].")
      .def_static("pi", &I::pi, "A tight enclosure of pi.")
      .def_static("half_pi", &I::half_pi, "A tight enclosure of pi / 2.")
      .def_static("two_pi", &I::two_pi, "A tight enclosure of 2 pi.")
      .def("lb", &I::lb, "The lower bound (inf for the empty set).")
      .def("ub", &I::ub, "The upper bound (-inf for the empty set).")
      .def("mid", &I::mid, "The midpoint (a finite value for an unbounded interval; NaN for the empty set).")
      .def("diam", &I::diam, "The width ub - lb, rounded up (NaN for the empty set).")
      .def("width", &I::width, "Same as diam().")
      .def("rad", &I::rad, "The smallest r with [mid - r, mid + r] containing x (NaN for the empty set).")
      .def("mag", &I::mag, "The magnitude: the largest |v| for v in the interval (NaN for the empty set).")
      .def("mig", &I::mig,
           "The mignitude: the smallest |v| for v in the interval (0 if it contains 0; NaN for the empty set).")
      .def("volume", &I::volume, "diam(), 0 for the empty set.")
      .def("is_empty", &I::is_empty, "True for the empty set.")
      .def("is_degenerate", &I::is_degenerate, "True when lb == ub (False for the empty set).")
      .def("is_unbounded", &I::is_unbounded, "True when a bound is infinite.")
      .def("is_bounded", &I::is_bounded, "True when both bounds are finite.")
      .def("is_all_reals", &I::is_all_reals, "True for [-inf, inf].")
      .def("contains", &I::contains, py::arg("x"), "True when the real x is in the interval.")
      .def("interior_contains", &I::interior_contains, py::arg("x"), "True when x is in the interior (lb < x < ub).")
      .def("is_subset", &I::is_subset, py::arg("y"), "True when self is a subset of y.")
      .def("is_strict_subset", &I::is_strict_subset, py::arg("y"),
           "True when self is a subset of y and differs from it.")
      .def("is_interior_subset", &I::is_interior_subset, py::arg("y"), "True when self is in the interior of y.")
      .def("is_superset", &I::is_superset, py::arg("y"), "True when y is a subset of self.")
      .def("intersects", &I::intersects, py::arg("y"), "True when self and y have a common point.")
      .def("is_disjoint", &I::is_disjoint, py::arg("y"), "True when self and y have no common point.")
      .def("bisect", &I::bisect, py::arg("ratio") = 0.5, "Two halves split at lb + ratio * diam.")
      .def("inflate", &I::inflate, py::arg("r"), "[lb - r, ub + r], rounded outward (a new interval).")
      .def("set_empty", &I::set_empty, "Makes this interval empty, in place.")
      .def("__contains__", &I::contains)
      .def(py::pickle([](const I& x) { return bounds_state(x); },
                      [](const py::tuple& t) {
                        return from_bounds(as_double(t[0], "Interval"), as_double(t[1], "Interval"));
                      }))
      .def("__repr__", &I::str)
      .def("__str__", &I::str)
      .def(py::self == py::self)
      .def(py::self != py::self)
      .def("__eq__", [](const I& a, double b) { return std::isfinite(b) && a == I(b); }, py::is_operator())
      .def("__ne__", [](const I& a, double b) { return !(std::isfinite(b) && a == I(b)); }, py::is_operator())
      .def(-py::self)
      .def(+py::self)
      .def("__abs__", [](const I& x) { return abs(x); });
  c.attr("__hash__") = py::none();  // mutable
  c.attr("__array_ufunc__") = py::none();  // numpy defers to our reflected operators

  // Binary operators with an Interval or a float on either side; in-place forms modify self.
  // An int goes through Interval(int) (the (I, I) forms come first): no rounding to nearest.
#define SILLAGE_BIN(name, rname, iname, op)                                                              \
  c.def(name, [](const I& a, const I& b) { return a op b; }, py::is_operator())                         \
      .def(name, [](const I& a, double b) { return a op I(b); }, py::is_operator())                     \
      .def(rname, [](const I& a, const I& b) { return b op a; }, py::is_operator())                     \
      .def(rname, [](const I& a, double b) { return I(b) op a; }, py::is_operator())                    \
      .def(iname, [](I& a, const I& b) -> I& { return a = a op b; }, py::is_operator(),                 \
           py::return_value_policy::reference)                                                          \
      .def(iname, [](I& a, double b) -> I& { return a = a op I(b); }, py::is_operator(),                \
           py::return_value_policy::reference);
  SILLAGE_BIN("__add__", "__radd__", "__iadd__", +)
  SILLAGE_BIN("__sub__", "__rsub__", "__isub__", -)
  SILLAGE_BIN("__mul__", "__rmul__", "__imul__", *)
  SILLAGE_BIN("__truediv__", "__rtruediv__", "__itruediv__", /)
  SILLAGE_BIN("__and__", "__rand__", "__iand__", &)
  SILLAGE_BIN("__or__", "__ror__", "__ior__", |)
#undef SILLAGE_BIN
  // An integral exponent is the integer power (x ** 2.0 == x ** 2), at any size.
  c.def("__pow__", [](const I& x, int n) { return pow(x, n); }, py::is_operator())
      .def("__pow__", [](const I& x, const py::int_& n) {
             const Interval e = int_enclosure(n);
             if (e.is_degenerate()) return pow(x, e.lb());
             return pow_big_int(x, e, PyObject_IsTrue(n.attr("__and__")(1).ptr()) == 1);
           }, py::is_operator())
      .def("__pow__", [](const I& x, double p) { return pow(x, p); }, py::is_operator())
      .def("__pow__", [](const I& x, const I& p) { return pow(x, p); }, py::is_operator());
}

void init_vector_class(py::module_& m) {
  using V = IntervalVector;
  py::class_<V, std::shared_ptr<V>> c(m, "IntervalVector",
                                      DOC(IntervalVector));
  def_copy(c);
  c.def(py::init([](const py::object& obj) { return vector_from(obj); }), py::arg("x"),
        "IntervalVector(n) (n copies of the real line), or from a list of intervals / numbers / "
        "pairs [lb, ub], or from an (n, 2) array of bounds.")
      .def(py::init([](std::size_t n, const py::object& x) { return V(n, to_interval(x, "IntervalVector(n, x)")); }),
           py::arg("n"), py::arg("x"), "n copies of the interval x.")
      .SILLAGE_DEF_STATIC(IntervalVector, from_point, py::arg("p"))
      .SILLAGE_DEF_STATIC(IntervalVector, empty, py::arg("n"))
      .SILLAGE_DEF(IntervalVector, size)
      .def("__len__", &V::size)
      .def("__getitem__", [](const V& v, long long i) { return v[py_index(i, v.size(), "IntervalVector")]; })
      .def("__getitem__",
           [](const V& v, const py::slice& s) {
             std::size_t start = 0, stop = 0, step = 0, n = 0;
             if (!s.compute(v.size(), &start, &stop, &step, &n)) throw py::error_already_set();
             std::vector<Interval> xs;
             for (std::size_t k = 0; k < n; ++k, start += step) xs.push_back(v[start]);
             return V(std::move(xs));
           })
      .def("__setitem__",
           [](V& v, long long i, const py::object& x) {
             const std::size_t k = py_index(i, v.size(), "IntervalVector");
             v[k] = to_interval(x, "IntervalVector[" + std::to_string(k) + "]");
           })
      .def("__iter__", [](const V& v) { return py::iter(py::cast(v.components())); })
      .SILLAGE_DEF(IntervalVector, subvector, py::arg("i"), py::arg("j"))
      .SILLAGE_DEF(IntervalVector, put, py::arg("start"), py::arg("x"))
      .SILLAGE_DEFS(IntervalVector, lb, ub, mid, diam, rad, mag, mig, volume, max_diam, min_diam)
      .SILLAGE_DEF(IntervalVector, extr_diam_index, py::arg("largest") = true)
      .SILLAGE_DEFS(IntervalVector, is_empty, is_unbounded, is_degenerate)
      .SILLAGE_DEF(IntervalVector, contains, py::arg("p"))
      .SILLAGE_DEF(IntervalVector, is_subset, py::arg("y"))
      .SILLAGE_DEF(IntervalVector, is_strict_subset, py::arg("y"))
      .SILLAGE_DEF(IntervalVector, is_interior_subset, py::arg("y"))
      .SILLAGE_DEF(IntervalVector, intersects, py::arg("y"))
      .def("bisect", py::overload_cast<double>(&V::bisect, py::const_), py::arg("ratio") = 0.5,
           DOC(IntervalVector, bisect, double))
      .def("bisect", py::overload_cast<std::size_t, double>(&V::bisect, py::const_), py::arg("i"),
           py::arg("ratio") = 0.5, DOC(IntervalVector, bisect, size_t_double))
      .SILLAGE_DEF(IntervalVector, inflate, py::arg("r"))
      .SILLAGE_DEF(IntervalVector, set_empty)
      .def("to_numpy", &vector_to_numpy, "An (n, 2) array of bounds (an empty component gives inf, -inf).")
      .def("__array__", [](const V& v, const py::object& dtype, const py::object&) {
             return as_array(vector_to_numpy(v), dtype);
           }, py::arg("dtype") = py::none(), py::arg("copy") = py::none())
      .def(py::pickle([](const V& v) { return py::object(vector_to_numpy(v)); },
                      [](const py::object& a) { return vector_from(a); }))
      .def("__repr__", &V::str)
      .def(py::self == py::self)
      .def(py::self != py::self)
      .def(-py::self)
      .def("__abs__", [](const V& v) { return abs(v); })
      .def(py::self + py::self)
      .def(py::self - py::self)
      .def(py::self & py::self)
      .def(py::self | py::self)
      .def(py::self += py::self)  // in place: the same Python object back
      .def(py::self -= py::self)
      .def(py::self &= py::self)
      .def(py::self |= py::self)
      .def(py::self * Interval())
      .def(Interval() * py::self)
      .def("__imul__", [](V& v, const Interval& s) -> V& { return v = s * v; }, py::is_operator(),
           py::return_value_policy::reference);
  c.attr("__hash__") = py::none();
  c.attr("__array_ufunc__") = py::none();
}

void init_matrix_class(py::module_& m) {
  using M = IntervalMatrix;
  py::class_<M, std::shared_ptr<M>> c(m, "IntervalMatrix", DOC(IntervalMatrix));
  def_copy(c);
  c.def(py::init([](std::size_t r, std::size_t k, const py::object& x) {
          return M(r, k, x.is_none() ? Interval() : to_interval(x, "IntervalMatrix(rows, cols, x)"));
        }),
        py::arg("rows"), py::arg("cols"), py::arg("x") = py::none(),
        "A rows x cols matrix whose entries are all x (default: the real line).")
      .def(py::init([](const py::object& obj) { return matrix_from(obj); }), py::arg("x"),
           "From a list of rows (each a list of intervals / numbers / pairs, or an IntervalVector), "
           "an (n, m, 2) array of bounds or an (n, m) array of points.")
      .SILLAGE_DEF_STATIC(IntervalMatrix, identity, py::arg("n"))
      .SILLAGE_DEF_STATIC(IntervalMatrix, empty, py::arg("rows"), py::arg("cols"))
      .SILLAGE_DEF_STATIC(IntervalMatrix, from_point, py::arg("p"))
      .SILLAGE_DEFS(IntervalMatrix, rows, cols)
      .def_property_readonly("shape", [](const M& a) { return py::make_tuple(a.rows(), a.cols()); }, "(rows, cols).")
      .def("__len__", &M::rows)
      .def("__getitem__", [](const M& a, std::pair<long long, long long> ij) {
             return a(py_index(ij.first, a.rows(), "IntervalMatrix row"), py_index(ij.second, a.cols(), "IntervalMatrix column"));
           })
      .def("__getitem__", [](const M& a, long long i) { return a.row(py_index(i, a.rows(), "IntervalMatrix row")); })
      .def("__setitem__", [](M& a, std::pair<long long, long long> ij, const py::object& x) {
             const std::size_t i = py_index(ij.first, a.rows(), "IntervalMatrix row"), j = py_index(ij.second, a.cols(), "IntervalMatrix column");
             a(i, j) = to_interval(x, "IntervalMatrix[" + std::to_string(i) + ", " + std::to_string(j) + "]");
           })
      .def("__setitem__", [](M& a, long long i, const py::object& r) {
             a.set_row(py_index(i, a.rows(), "IntervalMatrix row"), vector_from(r));
           })
      .SILLAGE_DEF(IntervalMatrix, row, py::arg("i"))
      .SILLAGE_DEF(IntervalMatrix, col, py::arg("j"))
      .SILLAGE_DEF(IntervalMatrix, set_row, py::arg("i"), py::arg("r"))
      .SILLAGE_DEF(IntervalMatrix, set_col, py::arg("j"), py::arg("c"))
      .SILLAGE_DEF(IntervalMatrix, transpose)
      .def_property_readonly("T", &M::transpose, "The transpose (a new matrix).")
      .SILLAGE_DEFS(IntervalMatrix, lb, ub, mid, diam, max_diam, is_empty, is_unbounded, is_degenerate)
      .SILLAGE_DEF(IntervalMatrix, contains, py::arg("p"))
      .SILLAGE_DEF(IntervalMatrix, is_subset, py::arg("y"))
      .SILLAGE_DEF(IntervalMatrix, is_interior_subset, py::arg("y"))
      .SILLAGE_DEF(IntervalMatrix, intersects, py::arg("y"))
      .SILLAGE_DEF(IntervalMatrix, inflate, py::arg("r"))
      .SILLAGE_DEF(IntervalMatrix, set_empty)
      .def("to_numpy", &matrix_to_numpy, "An (n, m, 2) array of bounds.")
      .def("__array__", [](const M& a, const py::object& dtype, const py::object&) {
             return as_array(matrix_to_numpy(a), dtype);
           }, py::arg("dtype") = py::none(), py::arg("copy") = py::none())
      .def(py::pickle([](const M& a) { return py::object(matrix_to_numpy(a)); },
                      [](const py::object& a) { return matrix_from(a); }))
      .def("__repr__", &M::str)
      .def(py::self == py::self)
      .def(py::self != py::self)
      .def(-py::self)
      .def("__abs__", [](const M& a) { return abs(a); })
      .def(py::self + py::self)
      .def(py::self - py::self)
      .def(py::self & py::self)
      .def(py::self | py::self)
      .def(py::self += py::self)  // in place: the same Python object back
      .def(py::self -= py::self)
      .def(py::self &= py::self)
      .def(py::self |= py::self)
      .def(py::self * py::self)
      .def(py::self * IntervalVector())
      .def(py::self * Interval())
      .def(Interval() * py::self)
      .def("__matmul__", [](const M& a, const M& b) { return a * b; }, py::is_operator())
      .def("__matmul__", [](const M& a, const IntervalVector& x) { return a * x; }, py::is_operator())
      .def(py::self *= Interval());
  c.attr("__hash__") = py::none();
  c.attr("__array_ufunc__") = py::none();
}

void init_functions(py::module_& m) {
  using I = Interval;
  using F1 = I (*)(const I&);
  using F2 = I (*)(const I&, const I&);
  m.def("sqr", static_cast<F1>(&sqr), py::arg("x"), DOC(sqr, Interval));
  m.def("sqrt", static_cast<F1>(&sqrt), py::arg("x"), DOC(sqrt, Interval));
  m.def("exp", static_cast<F1>(&exp), py::arg("x"), DOC(exp, Interval));
  m.def("log", static_cast<F1>(&log), py::arg("x"), DOC(log, Interval));
  m.def("pow", static_cast<I (*)(const I&, int)>(&pow), py::arg("x"), py::arg("n"), DOC(pow, Interval_int));
  m.def("pow", static_cast<I (*)(const I&, double)>(&pow), py::arg("x"), py::arg("p"),
        DOC(pow, Interval_double));
  m.def("pow", static_cast<F2>(&pow), py::arg("x"), py::arg("p"),
        DOC(pow, Interval_Interval));
  m.def("root", static_cast<I (*)(const I&, int)>(&root), py::arg("x"), py::arg("n"),
        DOC(root, Interval_int));
  m.def("sin", static_cast<F1>(&sin), py::arg("x"), DOC(sin, Interval));
  m.def("cos", static_cast<F1>(&cos), py::arg("x"), DOC(cos, Interval));
  m.def("tan", static_cast<F1>(&tan), py::arg("x"), DOC(tan, Interval));
  m.def("asin", static_cast<F1>(&asin), py::arg("x"), DOC(asin, Interval));
  m.def("acos", static_cast<F1>(&acos), py::arg("x"), DOC(acos, Interval));
  m.def("atan", static_cast<F1>(&atan), py::arg("x"), DOC(atan, Interval));
  m.def("atan2", static_cast<F2>(&atan2), py::arg("y"), py::arg("x"), DOC(atan2, Interval_Interval));
  m.def("sinh", static_cast<F1>(&sinh), py::arg("x"), DOC(sinh, Interval));
  m.def("cosh", static_cast<F1>(&cosh), py::arg("x"), DOC(cosh, Interval));
  m.def("tanh", static_cast<F1>(&tanh), py::arg("x"), DOC(tanh, Interval));
  m.def("abs", static_cast<F1>(&abs), py::arg("x"), DOC(abs, Interval));
  m.def("abs", [](const IntervalVector& x) { return abs(x); }, py::arg("x"), DOC(abs, IntervalVector));
  m.def("min", static_cast<F2>(&min), py::arg("x"), py::arg("y"), DOC(min, Interval_Interval));
  m.def("max", static_cast<F2>(&max), py::arg("x"), py::arg("y"), DOC(max, Interval_Interval));
  m.def("sign", static_cast<F1>(&sign), py::arg("x"),
        DOC(sign, Interval));
  m.def("hull", static_cast<F2>(&hull), py::arg("x"), py::arg("y"), DOC(hull, Interval_Interval));
  m.def("hull", [](const IntervalVector& x, const IntervalVector& y) { return hull(x, y); }, py::arg("x"),
        py::arg("y"), DOC(hull, IntervalVector_IntervalVector));
  m.SILLAGE_FN(dot, py::arg("x"), py::arg("y"));
  m.SILLAGE_FN(norm, py::arg("x"));
  m.SILLAGE_FN(div2, py::arg("c"), py::arg("b"));

  // Backward projections: Python intervals are values, so each returns the
  // contracted arguments as a tuple (a 1-tuple for one argument); an argument
  // with no solution comes back empty, and then all of them do.
  const char* doc1 = "Contracts x for y = f(x); returns the tuple (x,).";
  const char* doc2 = "Contracts x1, x2 for y = f(x1, x2); returns the tuple (x1, x2).";
#define SILLAGE_BWD1(name)                                                            \
  m.def(#name, [](const I& y, I x) {                                                  \
    name(y, x);                                                                       \
    return py::make_tuple(x);                                                         \
  }, py::arg("y"), py::arg("x"), doc1);
#define SILLAGE_BWD2(name)                                                            \
  m.def(#name, [](const I& y, I x1, I x2) {                                           \
    name(y, x1, x2);                                                                  \
    return py::make_tuple(x1, x2);                                                    \
  }, py::arg("y"), py::arg("x1"), py::arg("x2"), doc2);
  SILLAGE_BWD2(bwd_add)
  SILLAGE_BWD2(bwd_sub)
  SILLAGE_BWD2(bwd_mul)
  SILLAGE_BWD2(bwd_div)
  SILLAGE_BWD2(bwd_min)
  SILLAGE_BWD2(bwd_max)
  SILLAGE_BWD1(bwd_neg)
  SILLAGE_BWD1(bwd_sqr)
  SILLAGE_BWD1(bwd_sqrt)
  SILLAGE_BWD1(bwd_exp)
  SILLAGE_BWD1(bwd_log)
  SILLAGE_BWD1(bwd_sin)
  SILLAGE_BWD1(bwd_cos)
  SILLAGE_BWD1(bwd_tan)
  SILLAGE_BWD1(bwd_asin)
  SILLAGE_BWD1(bwd_acos)
  SILLAGE_BWD1(bwd_atan)
  SILLAGE_BWD1(bwd_sinh)
  SILLAGE_BWD1(bwd_cosh)
  SILLAGE_BWD1(bwd_tanh)
  SILLAGE_BWD1(bwd_abs)
  SILLAGE_BWD1(bwd_sign)
#undef SILLAGE_BWD1
#undef SILLAGE_BWD2
  m.def("bwd_pow", [](const I& y, I x, int n) {
    bwd_pow(y, x, n);
    return py::make_tuple(x);
  }, py::arg("y"), py::arg("x"), py::arg("n"), DOC(bwd_pow, Interval_Interval_int) ": contracts x; returns the tuple (x,).");
  m.def("bwd_pow", [](const I& y, I x, I p) {
    bwd_pow(y, x, p);
    return py::make_tuple(x, p);
  }, py::arg("y"), py::arg("x"), py::arg("p"), DOC(bwd_pow, Interval_Interval_Interval) ": contracts x and p; returns the tuple (x, p).");
  m.def("bwd_root", [](const I& y, I x, int n) {
    bwd_root(y, x, n);
    return py::make_tuple(x);
  }, py::arg("y"), py::arg("x"), py::arg("n"), DOC(bwd_root) ": contracts x; returns the tuple (x,).");
  m.def("bwd_atan2", [](const I& theta, I y, I x) {
    bwd_atan2(theta, y, x);
    return py::make_tuple(y, x);
  }, py::arg("theta"), py::arg("y"), py::arg("x"), DOC(bwd_atan2) ": contracts y and x; returns the tuple (y, x).");
}

}  // namespace

SILLAGE_BINDING(interval) {
  init_interval_class(m);
  init_vector_class(m);
  init_matrix_class(m);
  init_functions(m);
  // Numbers where an Interval is expected, lists / arrays where a box is.
  py::implicitly_convertible<py::float_, Interval>();
  py::implicitly_convertible<py::int_, Interval>();
  py::implicitly_convertible<py::list, IntervalVector>();
  py::implicitly_convertible<py::tuple, IntervalVector>();
  py::implicitly_convertible<py::array, IntervalVector>();
}

}  // namespace sillage::python
