// Function: parse, evaluate (natural, centered, batch over numpy arrays),
// differentiate, and contract with HC4-revise (in place on the given box).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <memory>

#include "bindings.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/interval/interval_matrix.h"

namespace sillage::python {
namespace {

// An (N, n, 2) array of bounds -> N boxes. NaN or inverted bounds raise sillage.Error.
std::vector<IntervalVector> boxes_from_array(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
                                             std::size_t n) {
  if (a.ndim() != 3 || static_cast<std::size_t>(a.shape(1)) != n || a.shape(2) != 2)
    throw DimensionError("Function.eval_batch: expected an array of shape (N, " + std::to_string(n) +
                         ", 2), got ndim " + std::to_string(a.ndim()));
  const auto r = a.unchecked<3>();
  std::vector<IntervalVector> xs(static_cast<std::size_t>(a.shape(0)), IntervalVector(n));
  for (py::ssize_t k = 0; k < a.shape(0); ++k)
    for (py::ssize_t i = 0; i < static_cast<py::ssize_t>(n); ++i) {
      try {
        xs[k][i] = Interval(r(k, i, 0), r(k, i, 1));
      } catch (const Error& e) {
        throw Error("Function.eval_batch: box " + std::to_string(k) + ", component " + std::to_string(i) + ": " +
                    e.what());
      }
    }
  return xs;
}

// N boxes of size m -> an (N, m, 2) array; an empty interval is (nan, nan).
py::array_t<double> boxes_to_array(const std::vector<IntervalVector>& ys, std::size_t m) {
  py::array_t<double> out({static_cast<py::ssize_t>(ys.size()), static_cast<py::ssize_t>(m), py::ssize_t{2}});
  auto w = out.mutable_unchecked<3>();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < ys.size(); ++k)
    for (std::size_t i = 0; i < m; ++i) {
      const Interval& y = ys[k][i];
      w(k, i, 0) = y.is_empty() ? nan : y.lb();
      w(k, i, 1) = y.is_empty() ? nan : y.ub();
    }
  return out;
}

// A box argument: an IntervalVector, or anything IntervalVector(...) accepts
// (a list of intervals / numbers / pairs, an (n, 2) array).
IntervalVector box_arg(const py::handle& x) {
  if (py::isinstance<IntervalVector>(x)) return x.cast<IntervalVector>();
  return py::type::of<IntervalVector>()(x).cast<IntervalVector>();
}

}  // namespace

void init_expr(py::module_& m) {
  py::class_<Function>(m, "Function", R"doc(
A real function f: R^n -> R^m given by variable names and an expression text,
e.g. Function(["x1", "x2"], "sqrt((x1-1)^2 + (x2-2)^2)"); a vector function is
written "(e1, e2, ...)". Every evaluation encloses the exact real result
(decimal constants such as 0.1 are enclosed rigorously).)doc")
      .def(py::init<const std::vector<std::string>&, const std::string&>(), py::arg("vars"), py::arg("expr"))
      .def("nb_vars", &Function::nb_vars, "Input dimension n.")
      .def("image_dim", &Function::image_dim, "Output dimension m (1 for a scalar function).")
      .def("var_names", &Function::var_names)
      .def(
          "eval",
          [](const Function& f, const py::object& x) -> py::object {
            const IntervalVector b = box_arg(x);
            if (f.image_dim() == 1) return py::cast(f.eval(b));
            return py::cast(f.eval_vector(b));
          },
          py::arg("x"),
          "Natural inclusion function on the box x: an Interval for a scalar function, an IntervalVector for a "
          "vector one.")
      .def(
          "eval_vector", [](const Function& f, const py::object& x) { return f.eval_vector(box_arg(x)); },
          py::arg("x"), "Natural inclusion function, always an IntervalVector.")
      .def(
          "centered_eval", [](const Function& f, const py::object& x) { return f.centered_eval(box_arg(x)); },
          py::arg("x"),
          "Mean-value form f(mid) + J([x])([x] - mid) intersected with the natural one (an IntervalVector).")
      .def(
          "jacobian", [](const Function& f, const py::object& x) { return f.jacobian(box_arg(x)); }, py::arg("x"),
          "Jacobian enclosure on the box, an m x n IntervalMatrix.")
      .def(
          "hc4_revise",
          [](const Function& f, IntervalVector& x, const py::object& y) {
            if (py::isinstance<Interval>(y)) return f.hc4_revise(x, y.cast<Interval>());
            if (py::isinstance<py::float_>(y) || py::isinstance<py::int_>(y))
              return f.hc4_revise(x, Interval(y.cast<double>()));
            return f.hc4_revise(x, box_arg(y));
          },
          py::arg("x"), py::arg("y"),
          "Contracts the box x in place so that f(x) in y (an Interval or a number for a scalar function, an "
          "IntervalVector otherwise). Returns False (x is then empty) when proven inconsistent.")
      .def("diff", &Function::diff, "Symbolic gradient (m = 1) or row-major Jacobian (size m*n), as a Function.")
      .def(
          "eval_batch",
          [](const Function& f, const py::object& xs) {
            std::vector<IntervalVector> boxes;
            if (py::isinstance<py::array>(xs)) {
              boxes = boxes_from_array(xs.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>(),
                                       f.nb_vars());
            } else {
              for (const py::handle& b : xs) boxes.push_back(box_arg(b));
            }
            std::vector<IntervalVector> ys;
            {
              py::gil_scoped_release release;
              ys = f.eval_batch(boxes);
            }
            return boxes_to_array(ys, f.image_dim());
          },
          py::arg("xs"),
          "Evaluates many boxes at once: xs is a list of IntervalVector or an (N, n, 2) array of bounds; returns "
          "an (N, m, 2) array of bounds, (nan, nan) for an empty interval.")
      .def("__getitem__", &Function::operator[], py::arg("i"), "The i-th component, a scalar Function.")
      .def("expr_str", &Function::expr_str)
      .def("__str__", &Function::str)
      .def("__repr__", [](const Function& f) { return "Function(" + f.str() + ")"; });
}

}  // namespace sillage::python
