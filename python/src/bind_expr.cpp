#include "bindings.h"

namespace sillage::python {
void init_expr(py::module_& /*m*/) {}
}  // namespace sillage::python
