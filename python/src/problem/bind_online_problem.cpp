// A problem file run online (sillage/problem/online_problem.h): OnlineProblem,
// the stream's JSON Lines and the replay against the batch solve. The GIL is
// kept: each row is microseconds, and on_update calls back into Python.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "docstrings.h"
#include "interruptible.h"
#include "sillage/problem/online_problem.h"
#include "sillage/problem/replay_problem.h"
#include "sillage/error.h"
#include "sillage/problem/stream_lines.h"

namespace sillage::python {

SILLAGE_BINDING(online_problem, "budget", "problem", "online") {
  py::class_<StreamRow>(m, "StreamRow", DOC(StreamRow))
      .def(py::init([](std::string table, std::optional<double> t, std::map<std::string, double> columns) {
             return StreamRow{std::move(table), t, std::move(columns)};
           }),
           py::arg("table") = "", py::arg("t") = py::none(), py::arg("columns") = std::map<std::string, double>{},
           "table (\"\": a tick), t (when it arrived; None: now), columns {name: value}.")
      .SILLAGE_FIELDS(StreamRow, table, t, columns)
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.");

  py::class_<OnlineProblem>(m, "OnlineProblem", DOC(OnlineProblem))
      .def(py::init<const Problem&, std::optional<OnlineOptions>>(), py::arg("problem"),
           py::arg("options") = py::none(), DOC(OnlineProblem, OnlineProblem))
      .SILLAGE_DEF(OnlineProblem, feed, py::arg("row"))
      .SILLAGE_DEF(OnlineProblem, on_update, py::arg("f"))
      .SILLAGE_DEFS(OnlineProblem, recorded_rows, outputs, waiting)
      .def("estimator", py::overload_cast<>(&OnlineProblem::estimator), py::return_value_policy::reference_internal,
           DOC(OnlineProblem, estimator))
      .def("__repr__", [](const OnlineProblem& op) {
        const OnlineEstimator& est = op.estimator();
        return "OnlineProblem(now=" + number_text(est.now()) + ", " + std::to_string(est.stats().slices) +
               " slices, " + std::to_string(op.waiting()) + " waiting)";
      });
  m.def("online_options", &online_options, py::arg("problem"), DOC(online_options));

  py::class_<ReplayOptions>(m, "ReplayOptions", DOC(ReplayOptions))
      .def(py::init([](double speed, std::optional<OnlineOptions> online,
                       std::function<void(const OnlineProblem&)> on_update, bool batch, const Budget& budget) {
             return ReplayOptions{speed, online, std::move(on_update), batch, budget};
           }),
           py::arg("speed") = 0.0, py::arg("online") = py::none(), py::arg("on_update") = py::none(),
           py::arg("batch") = true, py::arg("budget") = Budget{},
           "speed (N x real time, 0: as fast as possible), online, on_update, batch, budget.")
      .SILLAGE_FIELDS(ReplayOptions, speed, online, batch, budget)
      .def_readwrite("on_update", &ReplayOptions::on_update, "Called after each update of the estimate with the OnlineProblem.")
      .def("__repr__", [](const ReplayOptions& o) {
        return "ReplayOptions(speed=" + number_text(o.speed) + ", batch=" + (o.batch ? "True" : "False") + ")";
      });

  py::class_<ReplayResult>(m, "ReplayResult", DOC(ReplayResult))
      .SILLAGE_READONLY_FIELDS(ReplayResult, outputs, t, online, batch, latency, rows, refused, summary, truth_samples,
                               truth_inside, truth_unbounded, truth_misses, seconds)
      .SILLAGE_DEF(ReplayResult, latency_quantile, py::arg("q"))
      .SILLAGE_DEFS(ReplayResult, online_holds_batch)
      .SILLAGE_DEF(ReplayResult, mean_side_ratio, py::arg("after") = 0.0)
      .def("__repr__", [](const ReplayResult& r) {
        return "ReplayResult(" + std::to_string(r.rows) + " rows, " + std::to_string(r.t.size()) + " updates, status " +
               status_name(r.summary.status) + ", truth " + std::to_string(r.truth_inside) + "/" +
               std::to_string(r.truth_samples) + ")";
      });
  // On a worker thread, the GIL released: Ctrl-C (or options.budget.cancel) stops it between two rows.
  m.def(
      "replay_problem",
      [](const Problem& p, const ReplayOptions& o) {
        return run_interruptible(o.budget.cancel, [&](const CancelToken& token) {
          ReplayOptions with = o;
          with.budget.cancel = token;
          return replay_problem(p, with);
        });
      },
      py::arg("problem"), py::arg("options") = ReplayOptions(), DOC(replay_problem));
  m.def("replay_svg", &replay_svg, py::arg("problem"), py::arg("result"), DOC(replay_svg));
  m.def("replay_html", &replay_html, py::arg("problem"), py::arg("result"), DOC(replay_html));
  m.def("replay_json", &replay_json, py::arg("problem"), py::arg("result"), DOC(replay_json));
  m.def("parse_stream_line", &parse_stream_line, py::arg("line"), DOC(parse_stream_line));
  m.def("stream_line", &stream_line, py::arg("row"), DOC(stream_line));
  m.def("estimate_line", &estimate_line, py::arg("online_problem"), DOC(estimate_line));
}

}  // namespace sillage::python
