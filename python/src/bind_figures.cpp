#include "bindings.h"

namespace sillage::python {
void init_figures(py::module_& /*m*/) {}
}  // namespace sillage::python
