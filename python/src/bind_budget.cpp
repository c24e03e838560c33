// Budget and CancelToken (sillage/budget.h). The long algorithms take a
// Budget in their options; Ctrl-C stops them (interruptible.h).
#include "bindings.h"
#include "sillage/budget.h"

namespace sillage::python {

void init_budget(py::module_& m) {
  py::class_<CancelToken>(m, "CancelToken", "A flag that stops a computation (shared by its copies).")
      .def("__repr__", [](const CancelToken& c) { return std::string("CancelToken(cancelled=") + (c.cancelled() ? "True" : "False") + ")"; })
      .def(py::init<>(), "A token not cancelled.")
      .def("cancel", &CancelToken::cancel, "Ask the computations holding this token to stop (any thread).")
      .def("cancelled", &CancelToken::cancelled,
           "True once cancel() was called on this token or a copy of it (until reset()).")
      .def("reset", &CancelToken::reset, "Clears the flag, so that the token can be used again.");

  py::class_<Budget>(m, "Budget",
                     "Limits of a long computation: boxes, bytes of a paving, seconds (0: none) and a CancelToken.")
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
                     "Boxes stored or refined (for a paving: its nodes); 10^7 by default, 0: no limit.")
      .def_readwrite("max_bytes", &Budget::max_bytes,
                     "Memory of a paving's nodes (16 n + 8 bytes each in dimension n); 1 GiB by default, 0: no limit.")
      .def_readwrite("max_seconds", &Budget::max_seconds, "Wall-clock time in seconds; 0 (the default): no limit.")
      .def_readwrite("cancel", &Budget::cancel,
                     "The CancelToken checked at every box (Python sets it on Ctrl-C); raises Cancelled when set.")
      .def("__repr__", [](const Budget& b) {
        return "Budget(max_boxes=" + std::to_string(b.max_boxes) + ", max_bytes=" + std::to_string(b.max_bytes) +
               ", max_seconds=" + number_text(b.max_seconds) + ")";
      });
}

}  // namespace sillage::python
