#pragma once
// Arguments checked by hand where pybind11's casts would fail with a generic
// message ("incompatible function arguments", "Unable to cast"): a negative
// index, a NaN time, a value of the wrong type. Each gives a sillage error
// that says what was expected.
#include <cmath>
#include <cstddef>
#include <string>

#include <pybind11/numpy.h>

#include "bindings.h"
#include "sillage/error.h"
#include "sillage/interval/interval.h"

namespace sillage::python {

// The name of the Python type of h ("str", "function").
inline std::string type_name(const py::handle& h) { return py::str(py::type::handle_of(h).attr("__name__")); }

// A non-negative index (OutOfRangeError naming `where` otherwise).
inline std::size_t index_arg(py::ssize_t k, const char* where, const char* what) {
  if (k < 0) throw OutOfRangeError(std::string(where) + ": " + what + " " + std::to_string(k) + " is negative");
  return static_cast<std::size_t>(k);
}

// An Interval or a number (not NaN) given for `name`.
inline Interval interval_arg(const py::handle& h, const char* where, const char* name) {
  if (py::isinstance<Interval>(h)) return h.cast<Interval>();
  if (py::isinstance<py::float_>(h) || py::isinstance<py::int_>(h)) {
    const double x = h.cast<double>();
    if (std::isnan(x)) throw Error(std::string(where) + ": " + name + " is NaN, expected a time or an Interval");
    return Interval(x);
  }
  throw ArgumentTypeError(std::string(where) + ": " + name + " must be an Interval or a number, got " + type_name(h));
}

// A C-ordered array of doubles, converted from any numeric array.
using Bounds = py::array_t<double, py::array::c_style | py::array::forcecast>;

// h as an array of doubles (ArgumentTypeError naming `where` and `what` otherwise).
inline Bounds bounds_of(const py::handle& h, const char* where, const char* what) {
  Bounds a = Bounds::ensure(h);
  if (!a) {
    PyErr_Clear();
    throw ArgumentTypeError(std::string(where) + ": " + what + " must be an array of floats, got " + type_name(h));
  }
  return a;
}

// The shape of an array as Python prints it: "(3,)", "(4, 2)".
inline std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// Index i of a sequence of n, negative from the end; otherwise an IndexError
// that names `what`, the index and the size: "IntervalVector index 5 out of range (size 2)".
inline std::size_t py_index(long long i, std::size_t n, const char* what) {
  const long long k = i < 0 ? i + static_cast<long long>(n) : i;
  if (k < 0 || k >= static_cast<long long>(n))
    throw py::index_error(std::string(what) + " index " + std::to_string(i) + " out of range (size " + std::to_string(n) + ")");
  return static_cast<std::size_t>(k);
}

}  // namespace sillage::python
