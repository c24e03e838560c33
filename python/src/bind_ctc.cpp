#include "bindings.h"

namespace sillage::python {
void init_ctc(py::module_& /*m*/) {}
}  // namespace sillage::python
