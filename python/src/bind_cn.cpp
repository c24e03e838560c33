#include "bindings.h"

namespace sillage::python {
void init_cn(py::module_& /*m*/) {}
}  // namespace sillage::python
