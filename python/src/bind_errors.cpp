#include "bindings.h"
#include "sillage/error.h"

namespace sillage::python {
// sillage::Error becomes sillage.Error (a ValueError); its subclasses become
// subclasses of it. Registered base first: pybind11 tries the newest first.
void init_errors(py::module_& m) {
  const auto& error = py::register_exception<sillage::Error>(m, "Error", PyExc_ValueError);
  py::register_exception<DimensionError>(m, "DimensionError", error.ptr());
  py::register_exception<ParseError>(m, "ParseError", error.ptr());
}
}  // namespace sillage::python
