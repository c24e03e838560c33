// Python bindings of Trajectory and TrajectoryVector (tube/trajectory*.h).
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "arg_checks.h"
#include "bindings.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/trajectory_arithmetic.h"

namespace sillage::python {

void init_trajectory(py::module_& m) {
  py::class_<Trajectory, std::shared_ptr<Trajectory>> tc(
      m, "Trajectory",
      "A sampled (piecewise-linear), analytic (expression of t) or composite (arithmetic result) trajectory;\n"
      "evaluations are enclosures.");
  tc.def(py::init<const std::map<double, double>&>(), py::arg("samples"), "From a dict {t: x}.")
      .def(py::init<const std::vector<double>&, const std::vector<double>&>(), py::arg("times"), py::arg("values"),
           "Sampled: the values at the times (strictly increasing), linear in between.")
      .def(py::init<const std::string&, const Interval&>(), py::arg("expr"), py::arg("domain"),
           "Analytic: an expression of t over the domain.")
      .def(py::init<const Function&, const Interval&>(), py::arg("f"), py::arg("domain"),
           "Analytic: a Function of one variable t over the domain.")
      .def("is_sampled", &Trajectory::is_sampled, "True for a sampled trajectory.")
      .def("is_analytic", &Trajectory::is_analytic,
           "True for an analytic one (an expression of t); neither: a composite (arithmetic result).")
      .def("domain", &Trajectory::domain, "The time domain, an Interval.")
      .def("sample_times", &Trajectory::sample_times, "The sample times (sampled trajectories; [] otherwise).")
      .def("sample_values", &Trajectory::sample_values, "The sample values (sampled trajectories; [] otherwise).")
      .def("set", &Trajectory::set, py::arg("t"), py::arg("x"),
           "Adds the sample (t, x), replacing an existing one at t (sampled trajectories only).")
      .def("__call__", py::overload_cast<double>(&Trajectory::operator(), py::const_), py::arg("t"),
           "x(t) as an enclosing Interval (t a float), or x([t]) = {x(t) : t in [t]} (t an Interval).")
      .def("__call__", py::overload_cast<const Interval&>(&Trajectory::operator(), py::const_), py::arg("t"))
      .def("__repr__",
           [](const Trajectory& x) {
             if (x.is_analytic()) return "Trajectory(analytic, t=" + x.domain().str() + ")";
             if (!x.is_sampled()) return "Trajectory(composite, t=" + x.domain().str() + ")";
             return "Trajectory(sampled, " + std::to_string(x.sample_times().size()) + " points, t=" +
                    x.domain().str() + ")";
           })
      // Sampled trajectories pickle as their samples (bit-exact); an analytic one does not pickle.
      .def(py::pickle(
          [](const Trajectory& x) {
            if (!x.is_sampled()) {
              throw Error("Trajectory: only a sampled trajectory can be pickled, not an analytic or composite one");
            }
            return py::make_tuple(x.sample_times(), x.sample_values());
          },
          [](const py::tuple& st) {
            return Trajectory(st[0].cast<std::vector<double>>(), st[1].cast<std::vector<double>>());
          }));
  // Arithmetic (trajectory_arithmetic.h): composite trajectories over the common domain.
#define SILLAGE_TRAJ_BIN(name, rname, op)                                                                      \
  tc.def(name, [](const Trajectory& a, const Trajectory& b) { return a op b; }, py::is_operator(),            \
         "Composite trajectory over the common domain, evaluated as [a](t) " #op " [b](t).")                   \
      .def(name, [](const Trajectory& a, double b) { return a op b; }, py::is_operator())                     \
      .def(rname, [](const Trajectory& a, double b) { return b op a; }, py::is_operator());
  SILLAGE_TRAJ_BIN("__add__", "__radd__", +)
  SILLAGE_TRAJ_BIN("__sub__", "__rsub__", -)
  SILLAGE_TRAJ_BIN("__mul__", "__rmul__", *)
  SILLAGE_TRAJ_BIN("__truediv__", "__rtruediv__", /)
#undef SILLAGE_TRAJ_BIN
  tc.def("__neg__", [](const Trajectory& a) { return -a; })
      .def("__abs__", [](const Trajectory& a) { return abs(a); });
  tc.attr("__array_ufunc__") = py::none();
  using F1 = Trajectory (*)(const Trajectory&);
  m.def("sqr", static_cast<F1>(&sqr), py::arg("x"), "sqr of a trajectory (composite).");
  m.def("sqrt", static_cast<F1>(&sqrt), py::arg("x"), "sqrt of a trajectory (composite).");
  m.def("exp", static_cast<F1>(&exp), py::arg("x"), "exp of a trajectory (composite).");
  m.def("log", static_cast<F1>(&log), py::arg("x"), "log of a trajectory (composite).");
  m.def("sin", static_cast<F1>(&sin), py::arg("x"), "sin of a trajectory (composite).");
  m.def("cos", static_cast<F1>(&cos), py::arg("x"), "cos of a trajectory (composite).");
  m.def("tan", static_cast<F1>(&tan), py::arg("x"), "tan of a trajectory (composite).");
  m.def("atan", static_cast<F1>(&atan), py::arg("x"), "atan of a trajectory (composite).");
  m.def("abs", static_cast<F1>(&abs), py::arg("x"), "abs of a trajectory (composite).");
  m.def("atan2", static_cast<Trajectory (*)(const Trajectory&, const Trajectory&)>(&atan2), py::arg("y"),
        py::arg("x"), "atan2(y, x) of two trajectories (composite).");

  using TV = TrajectoryVector;
  py::class_<TV, std::shared_ptr<TV>> v(m, "TrajectoryVector",
                                        "n scalar trajectories, a vector trajectory over their common domain.");
  def_copy(v);
  v.def(py::init<std::vector<Trajectory>>(), py::arg("trajectories"), "From Trajectories (copied).")
      .def(py::init([](const std::vector<double>& times, const py::handle& values) {
             const Bounds a = bounds_of(values, "TrajectoryVector(times, values)", "values");
             if (a.ndim() != 2) {
               throw DimensionError("TrajectoryVector(times, values): values must have shape (k, n), got " +
                                    shape_text(a));
             }
             auto r = a.unchecked<2>();
             std::vector<std::vector<double>> pts(static_cast<std::size_t>(r.shape(0)));
             for (py::ssize_t j = 0; j < r.shape(0); ++j) {
               for (py::ssize_t i = 0; i < r.shape(1); ++i) pts[static_cast<std::size_t>(j)].push_back(r(j, i));
             }
             return TV(times, pts);
           }),
           py::arg("times"), py::arg("values"),
           "Sampled: values of shape (k, n), row j = the point at times[j] (k times, strictly increasing).")
      .def(py::init<const std::string&, const Interval&>(), py::arg("expr"), py::arg("domain"),
           "Analytic: a vector expression of t, e.g. '(cos(t), sin(t))', over the domain.")
      .def(py::init<const Function&, const Interval&>(), py::arg("f"), py::arg("domain"),
           "Analytic: a Function of one variable t (component i = f[i]).")
      .def("size", &TV::size, "The dimension n.")
      .def("__len__", &TV::size)
      .def("domain", &TV::domain, "The intersection of the components' domains.")
      .def("__getitem__", [](const TV& x, long long i) { return x[py_index(i, x.size(), "TrajectoryVector")]; }, py::arg("i"),
           "Component i (a copy; negative i from the end).")
      .def("__call__", py::overload_cast<double>(&TV::operator(), py::const_), py::arg("t"),
           "The box of the components' enclosures at t (a float) or over [t] (an Interval).")
      .def("__call__", py::overload_cast<const Interval&>(&TV::operator(), py::const_), py::arg("t"))
      .def("__neg__", [](const TV& a) { return -a; })
      .def("__add__", [](const TV& a, const TV& b) { return a + b; }, py::is_operator(),
           "Component-wise (same size, DimensionError otherwise).")
      .def("__sub__", [](const TV& a, const TV& b) { return a - b; }, py::is_operator())
      .def("__mul__", [](const TV& a, const Trajectory& b) { return a * b; }, py::is_operator(),
           "Every component times a scalar trajectory or a number.")
      .def("__mul__", [](const TV& a, double b) { return a * b; }, py::is_operator())
      .def("__rmul__", [](const TV& a, const Trajectory& b) { return b * a; }, py::is_operator())
      .def("__rmul__", [](const TV& a, double b) { return b * a; }, py::is_operator())
      .def("__truediv__", [](const TV& a, const Trajectory& b) { return a / b; }, py::is_operator())
      .def("__truediv__", [](const TV& a, double b) { return a / b; }, py::is_operator())
      .def("__repr__",
           [](const TV& x) {
             return "TrajectoryVector(dim " + std::to_string(x.size()) + ", t=" + x.domain().str() + ")";
           })
      // Pickled as its components (each must be sampled).
      .def(py::pickle([](const TV& x) { return py::make_tuple(x.components()); },
                      [](const py::tuple& st) { return TV(st[0].cast<std::vector<Trajectory>>()); }));
  v.attr("__array_ufunc__") = py::none();
}

}  // namespace sillage::python
