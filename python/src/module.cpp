// The _sillage extension module: every binding file registered with
// SILLAGE_BINDING (bindings.h), called in the order of their declared
// dependencies.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "bindings.h"

namespace py = pybind11;
using sillage::python::Binding;

PYBIND11_MODULE(_sillage, m) {
  m.doc() = "sillage: guaranteed state estimation by constraint programming over intervals and tubes";
  m.attr("__version__") = SILLAGE_VERSION;  // project(sillage VERSION ...) in CMakeLists.txt
  // A missing dependency or a cycle: std::runtime_error, which the import raises as ImportError.
  py::list called;
  for (const Binding* b : sillage::python::binding_order(sillage::python::binding_registry())) {
    b->init(m);
    called.append(py::make_tuple(b->name, py::tuple(py::cast(b->after)), b->file));
  }
  // (name, after, file) of each binding, in the order called; for the tests.
  m.attr("_bindings") = py::tuple(called);
  // The ordering alone, on [(name, [after...])], for the tests of its errors.
  m.def("_binding_order", [](const std::vector<std::pair<std::string, std::vector<std::string>>>& list) {
    std::vector<Binding> bindings;
    for (const auto& [name, after] : list) bindings.push_back({name, after, nullptr, "bind_" + name + ".cpp"});
    std::vector<std::string> names;
    for (const Binding* b : sillage::python::binding_order(bindings)) names.push_back(b->name);
    return names;
  });
}
