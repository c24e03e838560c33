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
#include "docstrings.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/trajectory_arithmetic.h"

namespace sillage::python {

SILLAGE_BINDING(trajectory, "expr", "interval") {
  py::class_<Trajectory, std::shared_ptr<Trajectory>> tc(
      m, "Trajectory",
      DOC(Trajectory));
  tc.def(py::init<const std::map<double, double>&>(), py::arg("samples"), DOC(Trajectory, Trajectory, map_double_double))
      .def(py::init<const std::vector<double>&, const std::vector<double>&>(), py::arg("times"), py::arg("values"),
           DOC(Trajectory, Trajectory, vector_double_vector_double))
      .def(py::init<const std::string&, const Interval&>(), py::arg("expr"), py::arg("domain"),
           DOC(Trajectory, Trajectory, string_Interval))
      .def(py::init<const Function&, const Interval&>(), py::arg("f"), py::arg("domain"),
           DOC(Trajectory, Trajectory, Function_Interval))
      .SILLAGE_DEFS(Trajectory, is_sampled, is_analytic, domain, sample_times, sample_values)
      .SILLAGE_DEF(Trajectory, set, py::arg("t"), py::arg("x"))
      .def("__call__", py::overload_cast<double>(&Trajectory::operator(), py::const_), py::arg("t"),
           DOC(Trajectory, op_call, double))
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
#define SILLAGE_TRAJ_BIN(op)                                                                             \
  tc.def(py::self op py::self, "Composite trajectory over the common domain, evaluated as [a](t) " #op   \
         " [b](t).")                                                                                     \
      .def(py::self op double())                                                                         \
      .def(double() op py::self);
  SILLAGE_TRAJ_BIN(+)
  SILLAGE_TRAJ_BIN(-)
  SILLAGE_TRAJ_BIN(*)
  SILLAGE_TRAJ_BIN(/)
#undef SILLAGE_TRAJ_BIN
  tc.def(-py::self)
      .def("__abs__", [](const Trajectory& a) { return abs(a); });
  tc.attr("__array_ufunc__") = py::none();
  using F1 = Trajectory (*)(const Trajectory&);
  m.def("sqr", static_cast<F1>(&sqr), py::arg("x"), DOC(sqr, Trajectory));
  m.def("sqrt", static_cast<F1>(&sqrt), py::arg("x"), DOC(sqrt, Trajectory));
  m.def("exp", static_cast<F1>(&exp), py::arg("x"), DOC(exp, Trajectory));
  m.def("log", static_cast<F1>(&log), py::arg("x"), DOC(log, Trajectory));
  m.def("sin", static_cast<F1>(&sin), py::arg("x"), DOC(sin, Trajectory));
  m.def("cos", static_cast<F1>(&cos), py::arg("x"), DOC(cos, Trajectory));
  m.def("tan", static_cast<F1>(&tan), py::arg("x"), DOC(tan, Trajectory));
  m.def("atan", static_cast<F1>(&atan), py::arg("x"), DOC(atan, Trajectory));
  m.def("abs", static_cast<F1>(&abs), py::arg("x"), DOC(abs, Trajectory));
  m.def("atan2", static_cast<Trajectory (*)(const Trajectory&, const Trajectory&)>(&atan2), py::arg("y"),
        py::arg("x"), DOC(atan2, Trajectory_Trajectory));

  using TV = TrajectoryVector;
  py::class_<TV, std::shared_ptr<TV>> v(m, "TrajectoryVector",
                                        DOC(TrajectoryVector));
  def_copy(v);
  v.def(py::init<std::vector<Trajectory>>(), py::arg("trajectories"), DOC(TrajectoryVector, TrajectoryVector, vector_Trajectory))
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
           DOC(TrajectoryVector, TrajectoryVector, string_Interval))
      .def(py::init<const Function&, const Interval&>(), py::arg("f"), py::arg("domain"),
           DOC(TrajectoryVector, TrajectoryVector, Function_Interval))
      .SILLAGE_DEF(TrajectoryVector, size)
      .def("__len__", &TV::size)
      .SILLAGE_DEF(TrajectoryVector, domain)
      .def("__getitem__", [](const TV& x, long long i) { return x[py_index(i, x.size(), "TrajectoryVector")]; }, py::arg("i"),
           DOC(TrajectoryVector, op_index))
      .def("__call__", py::overload_cast<double>(&TV::operator(), py::const_), py::arg("t"),
           DOC(TrajectoryVector, op_call, double))
      .def("__call__", py::overload_cast<const Interval&>(&TV::operator(), py::const_), py::arg("t"))
      .def(-py::self)
      .def(py::self + py::self, "Component-wise (same size, DimensionError otherwise).")
      .def(py::self - py::self)
      .def("__mul__", [](const TV& a, const Trajectory& b) { return a * b; }, py::is_operator(),
           "Every component times a scalar trajectory or a number.")
      .def(py::self * double())
      .def("__rmul__", [](const TV& a, const Trajectory& b) { return b * a; }, py::is_operator())
      .def(double() * py::self)
      .def("__truediv__", [](const TV& a, const Trajectory& b) { return a / b; }, py::is_operator())
      .def(py::self / double())
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
