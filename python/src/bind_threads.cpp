// ThreadLimit (sillage/threads.h): in Python a context manager, the limit in
// force inside the `with` block.
#include <memory>
#include <string>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/error.h"
#include "sillage/threads.h"

namespace sillage::python {

namespace {

struct ScopedThreadLimit {
  std::size_t threads;
  std::unique_ptr<ThreadLimit> active;  // inside the with block
};

}  // namespace

SILLAGE_BINDING(threads) {
  py::class_<ScopedThreadLimit>(m, "ThreadLimit",
                                "At most `threads` threads for sillage's parallel work inside the `with` block "
                                "(SIVIA, the t-plane, the SLAM's loops, the pointwise work on large tubes); "
                                "the results never depend on it. Error if threads < 1.")
      .def(py::init([](long long threads) {
             if (threads < 1) {
               throw Error("ThreadLimit: the number of threads must be at least 1, got " + std::to_string(threads));
             }
             return ScopedThreadLimit{static_cast<std::size_t>(threads), nullptr};
           }),
           py::arg("threads"),
           "A limit of `threads` threads (at least 1), in force inside a `with` block: `with sillage.ThreadLimit(1): ...`.")
      .def_readonly("threads", &ScopedThreadLimit::threads, DOC(ThreadLimit, threads))
      .def(
          "__enter__",
          [](ScopedThreadLimit& s) -> ScopedThreadLimit& {
            s.active = std::make_unique<ThreadLimit>(s.threads);
            return s;
          },
          py::return_value_policy::reference_internal)
      .def("__exit__", [](ScopedThreadLimit& s, const py::args&) {
        s.active.reset();
        return false;
      })
      .def_static("current", &ThreadLimit::current, DOC(ThreadLimit, current))
      .def("__repr__", [](const ScopedThreadLimit& s) { return "ThreadLimit(" + std::to_string(s.threads) + ")"; });
}

}  // namespace sillage::python
