// OnlineEstimator: estimation while the robot moves (docs/online.md). The
// updates run without the GIL (no worker thread: each is microseconds).
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/online/online_estimator.h"

namespace sillage::python {

std::shared_ptr<const Ctc> hold_ctc(const py::handle& h);  // bind_ctc.cpp
DomainRef to_domain_ref(const py::handle& h, std::size_t index);  // bind_cn.cpp

namespace {

// advance()'s inputs: a dict {name: box} or a list of (name, box) pairs.
std::vector<std::pair<std::string, IntervalVector>> inputs_arg(const py::object& inputs) {
  std::vector<std::pair<std::string, IntervalVector>> out;
  if (inputs.is_none()) return out;
  const py::iterable items = py::isinstance<py::dict>(inputs) ? py::iterable(inputs.attr("items")()) : py::iterable(inputs);
  for (const auto& item : items) {
    const auto pair = item.cast<py::tuple>();
    if (pair.size() != 2) throw Error("OnlineEstimator.advance: an input is a (name, box) pair");
    out.emplace_back(pair[0].cast<std::string>(), pair[1].cast<IntervalVector>());
  }
  return out;
}

}  // namespace

SILLAGE_BINDING(online, "cn", "ctc", "expr", "interval", "tube") {
  py::class_<OnlineOptions>(m, "OnlineOptions", DOC(OnlineOptions))
      .def(py::init([](double window, double forget_every, double ratio) {
             return OnlineOptions{window, forget_every, ratio};
           }),
           py::arg("window") = OnlineOptions().window, py::arg("forget_every") = 0.0, py::arg("ratio") = 0.01,
           "window=inf (keep everything), forget_every=0 (window/8), ratio=0.01.")
      .SILLAGE_FIELDS(OnlineOptions, window, forget_every, ratio)
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.");

  py::class_<OnlineStats>(m, "OnlineStats", DOC(OnlineStats))
      .SILLAGE_READONLY_FIELDS(OnlineStats, updates, last_seconds, total_seconds, slices, forgotten, observations, pending,
                               retired, contractors, contractor_runs, relayouts, layout_seconds)
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.");

  py::class_<OnlineEstimator>(m, "OnlineEstimator", DOC(OnlineEstimator))
      .def(py::init<double, OnlineOptions>(), py::arg("t0"), py::arg("options") = OnlineOptions(),
           DOC(OnlineEstimator, OnlineEstimator))
      .def("add_state", &OnlineEstimator::add_state, py::arg("name"), py::arg("dim"),
           py::arg("x0") = IntervalVector(), DOC(OnlineEstimator, add_state))
      .SILLAGE_DEF(OnlineEstimator, add_input, py::arg("name"), py::arg("dim"))
      .def("add_bounded", py::overload_cast<const std::string&, const IntervalVector&>(&OnlineEstimator::add_bounded),
           py::arg("name"), py::arg("value"), DOC(OnlineEstimator, add_bounded, string_IntervalVector))
      .def("add_bounded",
           py::overload_cast<const std::string&, const Function&, const IntervalVector&>(&OnlineEstimator::add_bounded),
           py::arg("name"), py::arg("bound"), py::arg("x0") = IntervalVector(), DOC(OnlineEstimator, add_bounded, string_Function_IntervalVector))
      .SILLAGE_DEF(OnlineEstimator, add_deriv, py::arg("x"), py::arg("v"))
      .def(
          "add",
          [](OnlineEstimator& est, const py::object& ctc, const std::vector<std::string>& tubes) {
            if (py::isinstance<NetworkCtc>(ctc)) {
              est.add(std::shared_ptr<const NetworkCtc>(ctc.cast<std::shared_ptr<NetworkCtc>>()), tubes);
            } else {
              est.add(hold_ctc(ctc), tubes);
            }
          },
          py::arg("ctc"), py::arg("tubes"),
          "Adds a constraint on the named tubes: a Ctc applied at every time to their components in order, or a "
          "NetworkCtc on the whole tubes (CtcIncrement, CtcSecondDeriv, ...). Before the first advance().")
      .def(
          "advance",
          [](OnlineEstimator& est, double t, const py::object& inputs) {
            const auto given = inputs_arg(inputs);
            py::gil_scoped_release unlocked;
            est.advance(t, given);
          },
          py::arg("t"), py::arg("inputs") = py::none(), DOC(OnlineEstimator, advance))
      .def(
          "observe",
          [](OnlineEstimator& est, const Interval& t, const py::object& state, const py::object& ctc,
             const py::iterable& extras) {
            std::vector<DomainRef> refs;
            for (const auto& h : extras) refs.push_back(to_domain_ref(h, refs.size() + 1));
            const auto states = py::isinstance<py::str>(state) ? std::vector<std::string>{state.cast<std::string>()}
                                                              : state.cast<std::vector<std::string>>();
            const auto held = hold_ctc(ctc);
            py::gil_scoped_release unlocked;
            return est.observe(t, states, held, refs);
          },
          py::arg("t"), py::arg("state"), py::arg("ctc"), py::arg("extras") = py::list(),
          "A measurement of the state (a name, or a list of names taken at the same time) at a time in [t]: "
          "ctc acts on (x1(t), ..., extras...). Held (pending()) until time passes the end of [t]. Returns the "
          "observation's number.")
      .SILLAGE_DEFS(OnlineEstimator, pending)
      .def("now", py::overload_cast<>(&OnlineEstimator::now, py::const_), DOC(OnlineEstimator, now, void))
      .def("now", py::overload_cast<const std::string&>(&OnlineEstimator::now, py::const_), py::arg("name"),
           DOC(OnlineEstimator, now, string))
      .SILLAGE_DEFS(OnlineEstimator, window_start, stats)
      .SILLAGE_DEF(OnlineEstimator, tube, py::arg("name"))
      .def("last_update", &OnlineEstimator::last_update, py::return_value_policy::copy,
           DOC(OnlineEstimator, last_update))
      .def("network", &OnlineEstimator::network, py::return_value_policy::reference_internal,
           DOC(OnlineEstimator, network))
      .def("options", &OnlineEstimator::options, py::return_value_policy::copy, DOC(OnlineEstimator, options))
      .def("__repr__", [](const OnlineEstimator& est) {
        const OnlineStats s = est.stats();
        return "OnlineEstimator(now=" + std::to_string(est.now()) + ", " + std::to_string(s.slices) + " slices, " +
               std::to_string(s.observations) + " observations)";
      });
}

}  // namespace sillage::python
