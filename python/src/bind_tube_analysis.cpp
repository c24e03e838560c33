#include "bindings.h"

namespace sillage::python {
void init_tube_analysis(py::module_& /*m*/) {}
}  // namespace sillage::python
