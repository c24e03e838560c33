#include "bindings.h"

namespace sillage::python {
void init_tube(py::module_& /*m*/) {}
}  // namespace sillage::python
