// Python bindings of the tube layer: TDomain, Trajectory, Tube (arithmetic,
// elementary functions as module-level overloads, numpy export), TubeVector
// (components are live references), builders and serialization.
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "arg_checks.h"
#include "bindings.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_builders.h"
#include "sillage/tube/tube_io.h"
#include "sillage/tube/tube_vector.h"

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

std::size_t py_index(long long i, std::size_t n) {
  if (i < 0) i += static_cast<long long>(n);
  if (i < 0 || i >= static_cast<long long>(n)) throw py::index_error("TubeVector index out of range");
  return static_cast<std::size_t>(i);
}

void init_tdomain(py::module_& m) {
  py::class_<TDomain, TD>(m, "TDomain",
                          "Time points t_0 < ... < t_N shared by the tubes of a problem; sample(t) splits "
                          "the slice containing t in every tube attached to it.")
      .def(py::init<double, double, double>(), py::arg("t0"), py::arg("tf"), py::arg("dt"),
           "Uniform: t_k = t0 + k*dt, the last slice possibly shorter, t_N = tf.")
      .def(py::init<std::vector<double>>(), py::arg("times"), "From the time points (strictly increasing).")
      .def("nb_slices", &TDomain::nb_slices)
      .def("t", &TDomain::t, py::arg("k"))
      .def("t0_tf", &TDomain::t0_tf)
      .def("times", [](const TDomain& td) { return std::vector<double>(td.times().begin(), td.times().end()); })
      .def("slice_index", &TDomain::slice_index, py::arg("t"),
           "Index of the slice containing t (at an inner time point: the slice it starts).")
      .def("slice_domain", &TDomain::slice_domain, py::arg("k"))
      .def("slice_width", &TDomain::slice_width, py::arg("k"), "Rigorous enclosure of t_{k+1} - t_k.")
      .def("is_time_point", &TDomain::is_time_point, py::arg("t"))
      .def("time_index", &TDomain::time_index, py::arg("t"), "The index k with t_k == t, or -1 if t is not a time point.")
      .def("sample", &TDomain::sample, py::arg("t"), "Adds the time point t; returns its index.")
      .def("nb_attached", &TDomain::nb_attached)
      .def("__repr__", [](const TDomain& td) {
        return "TDomain(" + td.t0_tf().str() + ", " + std::to_string(td.nb_slices()) + " slices)";
      });
}

void init_trajectory(py::module_& m) {
  py::class_<Trajectory, std::shared_ptr<Trajectory>>(
      m, "Trajectory", "A sampled (piecewise-linear) or analytic trajectory; evaluations are enclosures.")
      .def(py::init<const std::map<double, double>&>(), py::arg("samples"), "From a dict {t: x}.")
      .def(py::init<const std::vector<double>&, const std::vector<double>&>(), py::arg("times"), py::arg("values"))
      .def(py::init<const std::string&, const Interval&>(), py::arg("expr"), py::arg("domain"),
           "Analytic: an expression of t over the domain.")
      .def(py::init<const Function&, const Interval&>(), py::arg("f"), py::arg("domain"))
      .def("is_sampled", &Trajectory::is_sampled)
      .def("domain", &Trajectory::domain)
      .def("sample_times", &Trajectory::sample_times, "The sample times (sampled trajectories).")
      .def("sample_values", &Trajectory::sample_values)
      .def("set", &Trajectory::set, py::arg("t"), py::arg("x"))
      .def("__call__", py::overload_cast<double>(&Trajectory::operator(), py::const_), py::arg("t"))
      .def("__call__", py::overload_cast<const Interval&>(&Trajectory::operator(), py::const_), py::arg("t"));
}

void init_tube_class(py::module_& m) {
  using T = Tube;
  py::class_<T, std::shared_ptr<T>> c(m, "Tube",
                                      "A sliced enclosure of scalar trajectories: N slice codomains and N+1 gates "
                                      "on a TDomain. Copies (copy()) are attached to the same TDomain.");
  def_copy(c);
  c.def(py::init<TD, const std::string&>(), py::arg("tdomain"), py::arg("expr"),
        "From an expression of t, e.g. Tube(td, 'sin(t) + [-0.1,0.1]').")
      .def(py::init<TD, const Function&>(), py::arg("tdomain"), py::arg("f"))
      .def(py::init<TD, const Interval&>(), py::arg("tdomain"), py::arg("x") = Interval())
      .def(py::init<TD, const std::vector<Interval>&>(), py::arg("tdomain"), py::arg("slices"))
      .def(py::init<TD, const std::vector<Interval>&, const std::vector<Interval>&>(), py::arg("tdomain"),
           py::arg("slices"), py::arg("gates"))
      .def("tdomain", &T::tdomain)
      .def("nb_slices", &T::nb_slices)
      // Signed indices: -1 is an OutOfRangeError, not an argument mismatch.
      .def("slice", [](const T& x, py::ssize_t k) { return x.slice(index_arg(k, "Tube.slice", "slice")); },
           py::arg("k"))
      .def("gate", [](const T& x, py::ssize_t k) { return x.gate(index_arg(k, "Tube.gate", "gate")); }, py::arg("k"))
      .def(
          "set", [](T& x, const Interval& y, py::ssize_t k) { x.set(y, index_arg(k, "Tube.set(y, k)", "slice")); },
          py::arg("y"), py::arg("k"), "Slice k := y, its gates := y & the neighbouring slices.")
      .def("set", py::overload_cast<const Interval&>(&T::set), py::arg("y"))
      .def(
          "set_gate",
          [](T& x, py::ssize_t k, const Interval& y) { x.set_gate(index_arg(k, "Tube.set_gate", "gate"), y); },
          py::arg("k"), py::arg("y"))
      .def("codomain", &T::codomain)
      .def("volume", &T::volume)
      .def("thickness", &T::thickness, py::arg("k"))
      .def("max_thickness", &T::max_thickness)
      .def("is_empty", &T::is_empty)
      .def("is_subset", &T::is_subset, py::arg("y"))
      .def("contains", &T::contains, py::arg("trajectory"))
      .def("__call__", py::overload_cast<double>(&T::operator(), py::const_), py::arg("t"))
      .def("__call__", py::overload_cast<const Interval&>(&T::operator(), py::const_), py::arg("t"))
      .def("inverse", [](const T& x, const Interval& y) { return x.inverse(y); }, py::arg("y"),
           "Hull of the times where the tube meets y.")
      .def("inverse_components",
           [](const T& x, const Interval& y) {
             std::vector<Interval> cs;
             x.inverse(y, cs);
             return cs;
           },
           py::arg("y"), "The connected subsets of the inverse, in time order.")
      .def("slices_array", [](const T& x) { return bounds_array(x.slices()); }, "(N, 2) array of slice bounds.")
      .def("gates_array", [](const T& x) { return bounds_array(x.gates()); }, "(N+1, 2) array of gate bounds.")
      .def("__repr__", [](const T& x) {
        std::ostringstream os;
        os << x;
        return os.str();
      })
      .def(py::self == py::self)
      .def(py::self != py::self)
      .def(-py::self)
      .def("__abs__", [](const T& x) { return abs(x); })
      .def("__pow__", [](const T& x, int n) { return pow(x, n); }, py::is_operator())
      .def("__pow__", [](const T& x, double p) { return pow(x, p); }, py::is_operator())
      .def("__pow__", [](const T& x, const Interval& p) { return pow(x, p); }, py::is_operator());
  c.attr("__hash__") = py::none();
  c.attr("__array_ufunc__") = py::none();

  // With a Tube or an Interval (or a float) on either side; in-place forms modify self.
#define SILLAGE_TUBE_BIN(name, rname, iname, op)                                                     \
  c.def(name, [](const T& a, const T& b) { return a op b; }, py::is_operator())                       \
      .def(name, [](const T& a, const Interval& b) { return a op b; }, py::is_operator())             \
      .def(rname, [](const T& a, const Interval& b) { return b op a; }, py::is_operator())            \
      .def(iname, [](T& a, const T& b) -> T& { return a op## = b; }, py::is_operator(),               \
           py::return_value_policy::reference)                                                        \
      .def(iname, [](T& a, const Interval& b) -> T& { return a op## = b; }, py::is_operator(),        \
           py::return_value_policy::reference);
  SILLAGE_TUBE_BIN("__add__", "__radd__", "__iadd__", +)
  SILLAGE_TUBE_BIN("__sub__", "__rsub__", "__isub__", -)
  SILLAGE_TUBE_BIN("__mul__", "__rmul__", "__imul__", *)
  SILLAGE_TUBE_BIN("__truediv__", "__rtruediv__", "__itruediv__", /)
#undef SILLAGE_TUBE_BIN
  c.def("__and__", [](const T& a, const T& b) { return a & b; }, py::is_operator())
      .def("__or__", [](const T& a, const T& b) { return a | b; }, py::is_operator())
      .def("__iand__", [](T& a, const T& b) -> T& { return a &= b; }, py::is_operator(),
           py::return_value_policy::reference)
      .def("__ior__", [](T& a, const T& b) -> T& { return a |= b; }, py::is_operator(),
           py::return_value_policy::reference);
}

void init_tube_functions(py::module_& m) {
  using T = Tube;
  using F1 = T (*)(const T&);
  // Overloads chain onto the Interval ones defined by init_interval.
  m.def("sqr", static_cast<F1>(&sqr), py::arg("x"));
  m.def("sqrt", static_cast<F1>(&sqrt), py::arg("x"));
  m.def("exp", static_cast<F1>(&exp), py::arg("x"));
  m.def("log", static_cast<F1>(&log), py::arg("x"));
  m.def("sin", static_cast<F1>(&sin), py::arg("x"));
  m.def("cos", static_cast<F1>(&cos), py::arg("x"));
  m.def("tan", static_cast<F1>(&tan), py::arg("x"));
  m.def("asin", static_cast<F1>(&asin), py::arg("x"));
  m.def("acos", static_cast<F1>(&acos), py::arg("x"));
  m.def("atan", static_cast<F1>(&atan), py::arg("x"));
  m.def("sinh", static_cast<F1>(&sinh), py::arg("x"));
  m.def("cosh", static_cast<F1>(&cosh), py::arg("x"));
  m.def("tanh", static_cast<F1>(&tanh), py::arg("x"));
  m.def("abs", static_cast<F1>(&abs), py::arg("x"));
  m.def("sign", static_cast<F1>(&sign), py::arg("x"));
  m.def("pow", static_cast<T (*)(const T&, int)>(&pow), py::arg("x"), py::arg("n"));
  m.def("pow", static_cast<T (*)(const T&, double)>(&pow), py::arg("x"), py::arg("p"));
  m.def("pow", static_cast<T (*)(const T&, const Interval&)>(&pow), py::arg("x"), py::arg("p"));
  m.def("pow", static_cast<T (*)(const T&, const T&)>(&pow), py::arg("x"), py::arg("p"));
  m.def("root", static_cast<T (*)(const T&, int)>(&root), py::arg("x"), py::arg("n"));
  m.def("atan2", static_cast<T (*)(const T&, const T&)>(&atan2), py::arg("y"), py::arg("x"));
  m.def("atan2", static_cast<T (*)(const T&, const Interval&)>(&atan2), py::arg("y"), py::arg("x"));
  m.def("atan2", static_cast<T (*)(const Interval&, const T&)>(&atan2), py::arg("y"), py::arg("x"));
  m.def("min", static_cast<T (*)(const T&, const T&)>(&min), py::arg("x"), py::arg("y"));
  m.def("max", static_cast<T (*)(const T&, const T&)>(&max), py::arg("x"), py::arg("y"));
  m.def("hull", [](const T& x, const T& y) { return x | y; }, py::arg("x"), py::arg("y"));

  m.def("tube_from_data", py::overload_cast<TD, const Trajectory&, double>(&tube_from_data), py::arg("tdomain"),
        py::arg("data"), py::arg("error") = 0.0, "Interpolation of the data +- error.");
  m.def("tube_from_data", py::overload_cast<TD, const Trajectory&, double, const Interval&>(&tube_from_data),
        py::arg("tdomain"), py::arg("data"), py::arg("error"), py::arg("dx"),
        "Samples +- error and derivative bounds dx (thesis 3.3.2).");
  m.def("tube_from_bounds", &tube_from_bounds, py::arg("tdomain"), py::arg("lb"), py::arg("ub"));
  m.def("save_tube", py::overload_cast<const T&, const std::string&>(&save), py::arg("x"), py::arg("path"));
  m.def("save_tube", py::overload_cast<const TubeVector&, const std::string&>(&save), py::arg("x"),
        py::arg("path"));
  m.def("load_tube", py::overload_cast<const std::string&, TD>(&load_tube), py::arg("path"),
        py::arg("tdomain") = TD());
  m.def("load_tube_vector", py::overload_cast<const std::string&, TD>(&load_tube_vector), py::arg("path"),
        py::arg("tdomain") = TD());
}

void init_tube_vector(py::module_& m) {
  using V = TubeVector;
  py::class_<V, std::shared_ptr<V>> c(m, "TubeVector", "n tubes on one TDomain; v[i] is a live reference.");
  def_copy(c);
  c.def(py::init<TD, const std::string&>(), py::arg("tdomain"), py::arg("expr"),
        "From a vector expression of t, e.g. '(cos(t), sin(t))'.")
      .def(py::init<TD, const Function&>(), py::arg("tdomain"), py::arg("f"))
      .def(py::init<TD, std::size_t, const Interval&>(), py::arg("tdomain"), py::arg("n"), py::arg("x") = Interval())
      .def(py::init<TD, const IntervalVector&>(), py::arg("tdomain"), py::arg("x"))
      .def(py::init<std::vector<Tube>>(), py::arg("tubes"))
      .def("size", &V::size)
      .def("__len__", &V::size)
      .def("tdomain", &V::tdomain)
      .def("nb_slices", &V::nb_slices)
      // The component itself (a heap object of its own, shared): a live
      // reference that stays valid whatever happens to the vector, and that
      // ContractorNetwork identifies with the component of DomainRef.component.
      .def("__getitem__", [](V& v, long long i) { return v.shared_component(py_index(i, v.size())); },
           py::arg("i"))
      .def("__setitem__",
           [](V& v, long long i, const Tube& x) {
             Tube& xi = v[py_index(i, v.size())];
             if (x.tdomain() != xi.tdomain()) throw DimensionError("TubeVector[i] = x: x is on another TDomain");
             xi = x;
           },
           py::arg("i"), py::arg("x"))
      .def("subvector", &V::subvector, py::arg("i"), py::arg("j"), "Components i..j (inclusive), copied.")
      .def("slice", &V::slice, py::arg("k"))
      .def("gate", &V::gate, py::arg("k"))
      .def("__call__", py::overload_cast<double>(&V::operator(), py::const_), py::arg("t"))
      .def("__call__", py::overload_cast<const Interval&>(&V::operator(), py::const_), py::arg("t"))
      .def("codomain", &V::codomain)
      .def("volume", &V::volume)
      .def("max_thickness", &V::max_thickness)
      .def("is_empty", &V::is_empty)
      .def("is_subset", &V::is_subset, py::arg("y"))
      .def("contains", &V::contains, py::arg("trajectories"))
      .def("set", py::overload_cast<const IntervalVector&>(&V::set), py::arg("y"))
      .def(
          "set",
          [](V& x, const IntervalVector& y, py::ssize_t k) { x.set(y, index_arg(k, "TubeVector.set(y, k)", "slice")); },
          py::arg("y"), py::arg("k"))
      .def("set_gate", &V::set_gate, py::arg("k"), py::arg("y"))
      .def(py::self == py::self)
      .def(py::self != py::self)
      .def("__iand__", [](V& a, const V& b) -> V& { return a &= b; }, py::is_operator(),
           py::return_value_policy::reference)
      .def("__ior__", [](V& a, const V& b) -> V& { return a |= b; }, py::is_operator(),
           py::return_value_policy::reference)
      .def("__repr__", [](const V& v) {
        std::ostringstream os;
        os << v;
        return os.str();
      });
  c.attr("__hash__") = py::none();
}

}  // namespace

void init_tube(py::module_& m) {
  init_tdomain(m);
  init_trajectory(m);
  init_tube_class(m);
  init_tube_functions(m);
  init_tube_vector(m);
}

}  // namespace sillage::python
