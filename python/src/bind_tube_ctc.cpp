#include "bindings.h"

namespace sillage::python {
void init_tube_ctc(py::module_& /*m*/) {}
}  // namespace sillage::python
