// The size limit of the files sillage reads (sillage/read_file.h).
#include <cstdint>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/read_file.h"

namespace sillage::python {

SILLAGE_BINDING(read_file) {
  m.def("max_file_bytes", &max_file_bytes, DOC(max_file_bytes));
  m.def("set_max_file_bytes", &set_max_file_bytes, py::arg("bytes"), DOC(set_max_file_bytes));
  m.attr("DEFAULT_MAX_FILE_BYTES") = kDefaultMaxFileBytes;
}

}  // namespace sillage::python
