// Budget and CancelToken (sillage/budget.h). The long algorithms take a
// Budget in their options; Ctrl-C stops them (interruptible.h).
#include "bindings.h"
#include "docstrings.h"
#include "sillage/budget.h"

namespace sillage::python {

SILLAGE_BINDING(budget) {
  py::class_<CancelToken>(m, "CancelToken", DOC(CancelToken))
      .def("__repr__", [](const CancelToken& c) { return std::string("CancelToken(cancelled=") + (c.cancelled() ? "True" : "False") + ")"; })
      .def(py::init<>(), DOC(CancelToken, CancelToken))
      .def("cancel", &CancelToken::cancel, DOC(CancelToken, cancel))
      .def("cancelled", &CancelToken::cancelled,
           DOC(CancelToken, cancelled))
      .def("reset", &CancelToken::reset, DOC(CancelToken, reset));

  py::class_<Budget>(m, "Budget",
                     DOC(Budget))
      .def(py::init([](std::size_t max_boxes, std::size_t max_bytes, double max_seconds, const CancelToken* cancel) {
             Budget b{max_boxes, max_bytes, max_seconds, cancel ? *cancel : CancelToken{}};
             check_budget(b, "Budget");
             return b;
           }),
           py::arg("max_boxes") = Budget{}.max_boxes, py::arg("max_bytes") = Budget{}.max_bytes,
           py::arg("max_seconds") = 0.0, py::arg("cancel") = nullptr,
           "Limits for one computation; every limit is checked as the computation goes (raises BudgetExceeded, or "
           "Cancelled when `cancel` is set). Error on a negative max_seconds.")
      .def_readwrite("max_boxes", &Budget::max_boxes,
                     DOC(Budget, max_boxes))
      .def_readwrite("max_bytes", &Budget::max_bytes,
                     DOC(Budget, max_bytes))
      .def_readwrite("max_seconds", &Budget::max_seconds, DOC(Budget, max_seconds))
      .def_readwrite("cancel", &Budget::cancel,
                     "The CancelToken checked at every box (Python sets it on Ctrl-C); raises Cancelled when set.")
      .def("__repr__", [](const Budget& b) {
        return "Budget(max_boxes=" + std::to_string(b.max_boxes) + ", max_bytes=" + std::to_string(b.max_bytes) +
               ", max_seconds=" + number_text(b.max_seconds) + ")";
      });
}

}  // namespace sillage::python
