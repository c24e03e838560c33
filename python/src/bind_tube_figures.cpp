#include "bindings.h"

namespace sillage::python {
void init_tube_figures(py::module_& /*m*/) {}
}  // namespace sillage::python
