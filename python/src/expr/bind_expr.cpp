// The expression builder (Expr, ExprVar, operators and elementary functions
// on expressions) and Function: parse or build, evaluate (natural, centered,
// batch over numpy arrays), differentiate, and contract with HC4-revise (in
// place on the given box).
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/interval/interval_matrix.h"

namespace sillage::python {
namespace {

// x^n for a Python int n of any size, as x^n for a double n: an integer power
// ((x^2)^q x^r with n = 2q + r, down to an n that is a double, keeps the parity).
Expr pow_py_int(const Expr& x, const py::int_& n) {
  const Interval e = int_enclosure(n);
  if (e.is_degenerate()) return pow(x, e.lb());
  const Expr p = pow_py_int(sqr(x), n.attr("__rshift__")(1));
  return PyObject_IsTrue(n.attr("__and__")(1).ptr()) == 1 ? x * p : p;
}

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

// The builder: Expr, ExprVar (alias Variable), Op, the operators and the
// elementary functions on expressions. The functions are added as overloads of
// the Interval ones of the same name (bound earlier by init_interval): m.def
// chains a new overload onto an existing function of the module (sibling), so
// sillage.sqrt(Interval) keeps working and sillage.sqrt(Expr) builds a node.
void init_builder(py::module_& m) {
  py::enum_<Op>(m, "Op", DOC(Op))
      .value("Const", Op::Const)
      .value("Var", Op::Var)
      .value("Add", Op::Add)
      .value("Sub", Op::Sub)
      .value("Mul", Op::Mul)
      .value("Div", Op::Div)
      .value("Neg", Op::Neg)
      .value("Sqr", Op::Sqr)
      .value("Sqrt", Op::Sqrt)
      .value("PowInt", Op::PowInt)
      .value("Pow", Op::Pow)
      .value("Root", Op::Root)
      .value("Exp", Op::Exp)
      .value("Log", Op::Log)
      .value("Sin", Op::Sin)
      .value("Cos", Op::Cos)
      .value("Tan", Op::Tan)
      .value("Asin", Op::Asin)
      .value("Acos", Op::Acos)
      .value("Atan", Op::Atan)
      .value("Atan2", Op::Atan2)
      .value("Sinh", Op::Sinh)
      .value("Cosh", Op::Cosh)
      .value("Tanh", Op::Tanh)
      .value("Abs", Op::Abs)
      .value("Min", Op::Min)
      .value("Max", Op::Max)
      .value("Sign", Op::Sign);

  py::class_<Expr> e(m, "Expr", R"doc(
An expression of the C++ builder: an immutable, hash-consed node of the
expression DAG (building the same sub-expression twice gives the same node).
Expr(c) is the constant c (a number or an Interval; a float is the degenerate
interval [c, c]). Build with ExprVar, the operators + - * / ** (unary -) with
numbers and Intervals on either side, and sillage.sqr, sqrt, pow, root, exp, log,
sin, ..., atan2, abs, min, max, sign; then Function([x1, x2], expr).)doc");
  e.def(py::init([](const py::int_& c) { return Expr(int_enclosure(c)); }), py::arg("c"),
        "The constant c: an int exactly, or the tightest interval around it.")  // exact or outward
      .def(py::init<double>(), py::arg("c"), DOC(Expr, Expr, double))
      .def(py::init<const Interval&>(), py::arg("c"), DOC(Expr, Expr, Interval))
      .SILLAGE_DEFS(Expr, op, is_const)
      .def("__str__", &Expr::str)
      .def("__repr__", [](const Expr& x) { return "Expr(" + x.str() + ")"; })
      // Node identity, which hash-consing makes structural equality (C++ operator==).
      .def(py::self == py::self)
      .def(py::self != py::self)
      .def("__hash__", [](const Expr& x) { return std::hash<const ExprNode*>{}(x.get()); })
      .def(-py::self)
      .def("__pos__", [](const Expr& x) { return x; })
      .def("__abs__", [](const Expr& x) { return abs(x); });
  // Binary operators with an Expr, a number or an Interval on either side (numbers
  // and Intervals become constants; x += y rebinds x, as the C++ x += y does).
  // An int goes through Expr(int) (the (Expr, Expr) forms come first): enclosed, not rounded.
#define SILLAGE_EXPR_BIN(name, rname, op)                                                 \
  e.def(name, [](const Expr& a, const Expr& b) { return a op b; }, py::is_operator())     \
      .def(name, [](const Expr& a, double b) { return a op Expr(b); }, py::is_operator()) \
      .def(name, [](const Expr& a, const Interval& b) { return a op Expr(b); }, py::is_operator()) \
      .def(rname, [](const Expr& a, const Expr& b) { return b op a; }, py::is_operator())         \
      .def(rname, [](const Expr& a, double b) { return Expr(b) op a; }, py::is_operator())        \
      .def(rname, [](const Expr& a, const Interval& b) { return Expr(b) op a; }, py::is_operator());
  SILLAGE_EXPR_BIN("__add__", "__radd__", +)
  SILLAGE_EXPR_BIN("__sub__", "__rsub__", -)
  SILLAGE_EXPR_BIN("__mul__", "__rmul__", *)
  SILLAGE_EXPR_BIN("__truediv__", "__rtruediv__", /)
#undef SILLAGE_EXPR_BIN
  // x ** n: an int gives the integer power pow(x, n) (defined for x < 0), a float or
  // an Expr the real power (an integer-valued constant again gives pow(x, n)).
  e.def("__pow__", [](const Expr& x, int n) { return pow(x, n); }, py::is_operator())
      .def("__pow__", [](const Expr& x, const py::int_& n) { return pow_py_int(x, n); }, py::is_operator())
      .def("__pow__", [](const Expr& x, double p) { return pow(x, p); }, py::is_operator())
      .def("__pow__", [](const Expr& x, const Expr& p) { return pow(x, p); }, py::is_operator())
      .def("__rpow__", [](const Expr& p, double x) { return pow(Expr(x), p); }, py::is_operator())
      .def("__rpow__", [](const Expr& p, const Interval& x) { return pow(Expr(x), p); }, py::is_operator());

  py::class_<ExprVar, Expr>(m, "ExprVar", DOC(ExprVar))
      .def(py::init<const std::string&>(), py::arg("name"), DOC(ExprVar, ExprVar))
      .SILLAGE_DEF(ExprVar, name)
      .def("__repr__", [](const ExprVar& v) { return "ExprVar(" + py::repr(py::str(v.name())).cast<std::string>() + ")"; });
  m.attr("Variable") = m.attr("ExprVar");  // C++: using Variable = ExprVar

  // Numbers and Intervals wherever an Expr is expected (sillage.atan2(x2, 1), Function([x], 2)).
  py::implicitly_convertible<py::float_, Expr>();
  py::implicitly_convertible<py::int_, Expr>();
  py::implicitly_convertible<Interval, Expr>();

  m.SILLAGE_FN(expr_pi);
  using E1 = Expr (*)(const Expr&);
  using E2 = Expr (*)(const Expr&, const Expr&);
  m.def("sqr", static_cast<E1>(&sqr), py::arg("x"), DOC(sqr, Expr));
  m.def("sqrt", static_cast<E1>(&sqrt), py::arg("x"), DOC(sqrt, Expr));
  m.def("exp", static_cast<E1>(&exp), py::arg("x"), DOC(exp, Expr));
  m.def("log", static_cast<E1>(&log), py::arg("x"), DOC(log, Expr));
  m.def("pow", static_cast<Expr (*)(const Expr&, int)>(&pow), py::arg("x"), py::arg("n"),
        DOC(pow, Expr_int));
  m.def("pow", static_cast<Expr (*)(const Expr&, double)>(&pow), py::arg("x"), py::arg("p"),
        DOC(pow, Expr_double));
  m.def("pow", static_cast<E2>(&pow), py::arg("x"), py::arg("p"), DOC(pow, Expr_Expr));
  m.def("root", static_cast<Expr (*)(const Expr&, int)>(&root), py::arg("x"), py::arg("n"),
        DOC(root, Expr_int));
  m.def("sin", static_cast<E1>(&sin), py::arg("x"), DOC(sin, Expr));
  m.def("cos", static_cast<E1>(&cos), py::arg("x"), DOC(cos, Expr));
  m.def("tan", static_cast<E1>(&tan), py::arg("x"), DOC(tan, Expr));
  m.def("asin", static_cast<E1>(&asin), py::arg("x"), DOC(asin, Expr));
  m.def("acos", static_cast<E1>(&acos), py::arg("x"), DOC(acos, Expr));
  m.def("atan", static_cast<E1>(&atan), py::arg("x"), DOC(atan, Expr));
  m.def("atan2", static_cast<E2>(&atan2), py::arg("y"), py::arg("x"), DOC(atan2, Expr_Expr));
  m.def("sinh", static_cast<E1>(&sinh), py::arg("x"), DOC(sinh, Expr));
  m.def("cosh", static_cast<E1>(&cosh), py::arg("x"), DOC(cosh, Expr));
  m.def("tanh", static_cast<E1>(&tanh), py::arg("x"), DOC(tanh, Expr));
  m.def("abs", static_cast<E1>(&abs), py::arg("x"), DOC(abs, Expr));
  m.def("min", static_cast<E2>(&min), py::arg("x"), py::arg("y"), DOC(min, Expr_Expr));
  m.def("max", static_cast<E2>(&max), py::arg("x"), py::arg("y"), DOC(max, Expr_Expr));
  m.def("sign", static_cast<E1>(&sign), py::arg("x"), DOC(sign, Expr));
}

}  // namespace

SILLAGE_BINDING(expr, "interval") {
  init_builder(m);
  py::class_<Function>(m, "Function", R"doc(
A real function f: R^n -> R^m given by variable names and an expression text,
e.g. Function(["x1", "x2"], "sqrt((x1-1)^2 + (x2-2)^2)"); a vector function is
written "(e1, e2, ...)". Or from the builder: Function([x1, x2], expr) or
Function([x1, x2], [e1, e2]) with x1 = ExprVar("x1"), ... Every evaluation
encloses the exact real result (decimal constants such as 0.1 in a text are
enclosed rigorously; a float in the builder is the degenerate interval).)doc")
      .def(py::init<const std::vector<std::string>&, const std::string&>(), py::arg("vars"), py::arg("expr"),
           DOC(Function, Function, vector_string_string))
      .def(py::init<const std::vector<ExprVar>&, const Expr&>(), py::arg("vars"), py::arg("expr"),
           DOC(Function, Function, vector_ExprVar_Expr))
      .def(py::init<const std::vector<ExprVar>&, const std::vector<Expr>&>(), py::arg("vars"), py::arg("exprs"),
           DOC(Function, Function, vector_ExprVar_vector_Expr))
      .SILLAGE_DEFS(Function, nb_vars, image_dim, var_names, exprs, tape_size)
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
          "jacobian_vector", [](const Function& f, const py::object& x) { return f.jacobian_vector(box_arg(x)); },
          py::arg("x"), "Jacobian enclosure on the box, row-major, as an IntervalVector of size m*n.")
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
      .SILLAGE_DEF(Function, diff)
      .def(
          "eval_batch",
          [](const Function& f, const py::object& xs) {
            std::vector<IntervalVector> boxes;
            if (is_ndarray(xs)) {
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
      .def("__getitem__", &Function::operator[], py::arg("i"), DOC(Function, op_index))
      .SILLAGE_DEF(Function, expr_str)
      .def("__str__", &Function::str)
      .def("__repr__", [](const Function& f) { return "Function(" + f.str() + ")"; });
}

}  // namespace sillage::python
