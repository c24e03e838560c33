#include "bindings.h"
#include "sillage/error.h"

namespace sillage::python {
// sillage::Error (and its subclasses) become sillage.Error, a subclass of ValueError.
void init_errors(py::module_& m) { py::register_exception<sillage::Error>(m, "Error", PyExc_ValueError); }
}  // namespace sillage::python
