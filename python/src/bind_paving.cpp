#include "bindings.h"

namespace sillage::python {
void init_paving(py::module_& /*m*/) {}
}  // namespace sillage::python
