// explain_empty in Python: which statements of a problem without solution to relax.
#include <pybind11/stl.h>

#include "bindings.h"
#include "docstrings.h"
#include "interruptible.h"
#include "sillage/problem/explain_empty.h"

namespace sillage::python {

SILLAGE_BINDING(explain, "problem", "budget", "cn", "interval") {
  py::enum_<ItemKind>(m, "ItemKind", DOC(ItemKind))
      .value("Bound", ItemKind::Bound)
      .value("Gate", ItemKind::Gate)
      .value("TableBound", ItemKind::TableBound)
      .value("Constraint", ItemKind::Constraint)
      .value("Rows", ItemKind::Rows);
  py::enum_<TrialOutcome>(m, "TrialOutcome", DOC(TrialOutcome))
      .value("Empty", TrialOutcome::Empty)
      .value("NotEmpty", TrialOutcome::NotEmpty)
      .value("Stopped", TrialOutcome::Stopped);
  py::class_<ExplainItem>(m, "ExplainItem", DOC(ExplainItem))
      .SILLAGE_READONLY_FIELDS(ExplainItem, kind, label, stated, var, index, first_row, last_row, nb_rows, time, all_rows)
      .def_property_readonly("file", [](const ExplainItem& it) { return it.pos.file; }, "The problem file that states it.")
      .def_property_readonly("line", [](const ExplainItem& it) { return it.pos.line; }, "Its line in that file (1-based).")
      .SILLAGE_DEFS(ExplainItem, str)
      .def("__repr__", [](const ExplainItem& it) { return "ExplainItem(" + it.str() + ")"; });
  py::class_<ProvenValue>(m, "ProvenValue", DOC(ProvenValue))
      .SILLAGE_READONLY_FIELDS(ProvenValue, what, stated, proven, window, pieces)
      .SILLAGE_DEFS(ProvenValue, disjoint, proven_text)
      .def("__repr__", [](const ProvenValue& v) {
        return "ProvenValue(" + v.what + " in " + v.proven_text() + ", stated " + v.stated.str() + ")";
      });
  py::class_<Relaxation>(m, "Relaxation", DOC(Relaxation))
      .SILLAGE_READONLY_FIELDS(Relaxation, items, values, minimal, seconds)
      .def("__repr__", [](const Relaxation& r) {
        return "Relaxation(" + std::to_string(r.items.size()) + " items, " + std::to_string(r.values.size()) + " values" +
               (r.minimal ? ", minimal" : "") + ")";
      });
  py::class_<ExplainTrial>(m, "ExplainTrial", DOC(ExplainTrial))
      .SILLAGE_READONLY_FIELDS(ExplainTrial, items, outcome, seconds, probe, error)
      .def("__repr__", [](const ExplainTrial& t) {
        return "ExplainTrial(" + std::to_string(t.items.size()) + " items, " + outcome_name(t.outcome) +
               (t.probe.empty() ? "" : ", probe " + t.probe) + ")";
      });
  py::class_<ExplainOptions>(m, "ExplainOptions", DOC(ExplainOptions))
      .def(py::init<>(), "The defaults: the failing δ, 30 s, rows narrowed to single rows.")
      .SILLAGE_FIELDS(ExplainOptions, delta, scheduling, max_seconds, refine_rows, min_rows, budget)
      .def("__repr__", [](const ExplainOptions& o) {
        return "ExplainOptions(max_seconds=" + number_text(o.max_seconds) + ", refine_rows=" +
               (o.refine_rows ? "True" : "False") + ", min_rows=" + std::to_string(o.min_rows) + ")";
      });
  py::class_<Explanation>(m, "Explanation", DOC(Explanation))
      .SILLAGE_READONLY_FIELDS(Explanation, empty, why_empty, delta, slices, items, relaxations, trials, complete, stopped,
                               seconds)
      .SILLAGE_DEFS(Explanation, str)
      .def("__str__", &Explanation::str)
      .def("__repr__", [](const Explanation& e) {
        return "Explanation(" + std::string(e.empty ? "empty" : "not empty") + ", " + std::to_string(e.relaxations.size()) +
               " relaxations, " + std::to_string(e.trials.size()) + " trials" + (e.complete ? "" : ", partial") + ")";
      });
  m.SILLAGE_FN(explain_items, py::arg("problem"));
  m.SILLAGE_FN(row_runs, py::arg("problem"), py::arg("rows"), py::arg("parts"));
  m.SILLAGE_FN(relaxed_problem, py::arg("problem"), py::arg("items"), py::arg("relaxed"));
  m.SILLAGE_FN(explanation_json, py::arg("explanation"));
  // On a worker thread, the GIL released: Ctrl-C cancels the trials (KeyboardInterrupt).
  m.def(
      "explain_empty",
      [](const Problem& p, const std::optional<ExplainOptions>& o) {
        const ExplainOptions options = o ? *o : ExplainOptions{};
        return run_interruptible(options.budget.cancel, [&](const CancelToken& token) {
          return explain_empty(p, with_token(options, token));
        });
      },
      py::arg("problem"), py::arg("options") = py::none(), DOC(explain_empty, Problem_ExplainOptions));
  m.def(
      "explain_empty",
      [](const Problem& p, const SolveResult& r, const std::optional<ExplainOptions>& o) {
        const ExplainOptions options = o ? *o : ExplainOptions{};
        return run_interruptible(options.budget.cancel, [&](const CancelToken& token) {
          return explain_empty(p, r, with_token(options, token));
        });
      },
      py::arg("problem"), py::arg("result"), py::arg("options") = py::none(),
      DOC(explain_empty, Problem_SolveResult_ExplainOptions));
}

}  // namespace sillage::python
