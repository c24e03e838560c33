// Budget and CancelToken (sillage/budget.h), and the outcome of the long
// computations: Status, Summary, Progress (sillage/outcome.h). The long
// algorithms take a Budget in their options; Ctrl-C stops them
// (interruptible.h).
#include <memory>
#include <optional>
#include <utility>

#include <pybind11/stl.h>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/budget.h"

namespace sillage::python {

namespace {

// A Python callable as the progress hook: called with the GIL from whatever
// thread of the run reports, and released with the GIL from whatever thread
// drops the last copy of the budget.
ProgressHook python_hook(py::function f) {
  std::shared_ptr<py::function> held(new py::function(std::move(f)), [](py::function* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
  return [held](const Progress& p) {
    py::gil_scoped_acquire gil;
    (*held)(p);
  };
}

}  // namespace

SILLAGE_BINDING(budget) {
  py::enum_<Status>(m, "Status", DOC(Status))
      .value("Converged", Status::Converged, DOC(Status, Converged))
      .value("Stopped", Status::Stopped, DOC(Status, Stopped))
      .value("Cancelled", Status::Cancelled, DOC(Status, Cancelled))
      .value("NoSolution", Status::NoSolution, DOC(Status, NoSolution));

  py::class_<Summary>(m, "Summary", DOC(Summary))
      .def(py::init<>(), "A summary of nothing yet: Converged, no reason, zero counters.")
      .def_readonly("status", &Summary::status, DOC(Summary, status))
      .def_readonly("reason", &Summary::reason, DOC(Summary, reason))
      .def_readonly("rounds", &Summary::rounds, DOC(Summary, rounds))
      .def_readonly("work", &Summary::work, DOC(Summary, work))
      .def_readonly("seconds", &Summary::seconds, DOC(Summary, seconds))
      .def("finished", &Summary::finished, DOC(Summary, finished))
      .def("__str__", &Summary::str, DOC(Summary, str))
      .def("__repr__", [](const py::object& self) { return fields_repr(self); });

  py::class_<Progress>(m, "Progress", DOC(Progress))
      .def_property_readonly("where", [](const Progress& p) { return std::string(p.where); }, DOC(Progress, where))
      .def_readonly("round", &Progress::round, DOC(Progress, round))
      .def_readonly("work", &Progress::work, DOC(Progress, work))
      .def_readonly("seconds", &Progress::seconds, DOC(Progress, seconds))
      .def("__repr__", [](const py::object& self) { return fields_repr(self); });

  py::class_<CancelToken>(m, "CancelToken", DOC(CancelToken))
      .def("__repr__", [](const CancelToken& c) { return std::string("CancelToken(cancelled=") + (c.cancelled() ? "True" : "False") + ")"; })
      .def(py::init<>(), DOC(CancelToken, CancelToken))
      .def("cancel", &CancelToken::cancel, DOC(CancelToken, cancel))
      .def("cancelled", &CancelToken::cancelled,
           DOC(CancelToken, cancelled))
      .def("reset", &CancelToken::reset, DOC(CancelToken, reset));

  py::class_<Budget>(m, "Budget",
                     DOC(Budget))
      .def(py::init([](std::size_t max_boxes, std::size_t max_bytes, double max_seconds, const CancelToken* cancel,
                       const std::optional<py::function>& progress, std::size_t progress_every) {
             Budget b;
             b.max_boxes = max_boxes;
             b.max_bytes = max_bytes;
             b.max_seconds = max_seconds;
             if (cancel) b.cancel = *cancel;
             if (progress) b.progress = python_hook(*progress);
             b.progress_every = progress_every;
             check_budget(b, "Budget");
             return b;
           }),
           py::arg("max_boxes") = Budget{}.max_boxes, py::arg("max_bytes") = Budget{}.max_bytes,
           py::arg("max_seconds") = 0.0, py::arg("cancel") = nullptr, py::arg("progress") = py::none(),
           py::arg("progress_every") = Budget{}.progress_every,
           "Limits for one computation; every limit is checked as the computation goes (raises BudgetExceeded, or "
           "Cancelled when `cancel` is set; the *_run forms return the result so far with a Summary instead). "
           "progress(Progress) is called every progress_every units of work. Error on a negative max_seconds.")
      .def_readwrite("max_boxes", &Budget::max_boxes,
                     DOC(Budget, max_boxes))
      .def_readwrite("max_bytes", &Budget::max_bytes,
                     DOC(Budget, max_bytes))
      .def_readwrite("max_seconds", &Budget::max_seconds, DOC(Budget, max_seconds))
      .def_readwrite("cancel", &Budget::cancel,
                     "The CancelToken checked at every box (Python sets it on Ctrl-C); raises Cancelled when set.")
      .def_property(
          "progress",
          [](const Budget& b) -> py::object {
            if (!b.progress) return py::none();
            return py::cpp_function([hook = b.progress](const Progress& p) { hook(p); });
          },
          [](Budget& b, const std::optional<py::function>& f) { b.progress = f ? python_hook(*f) : ProgressHook{}; },
          DOC(Budget, progress))
      .def_readwrite("progress_every", &Budget::progress_every, DOC(Budget, progress_every))
      .def("__repr__", [](const Budget& b) {
        return "Budget(max_boxes=" + std::to_string(b.max_boxes) + ", max_bytes=" + std::to_string(b.max_bytes) +
               ", max_seconds=" + number_text(b.max_seconds) + ")";
      });
}

}  // namespace sillage::python
