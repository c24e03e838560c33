#include "bindings.h"

namespace sillage::python {

std::string fields_repr(const py::object& self) {
  const py::object type = py::type::of(self);
  const py::object property = py::module_::import("builtins").attr("property");
  std::string s = py::str(type.attr("__name__")).cast<std::string>() + "(";
  const char* sep = "";
  for (const auto& item : py::dict(type.attr("__dict__"))) {
    const std::string key = py::str(item.first);
    if (key.empty() || key[0] == '_' || !py::isinstance(item.second, property)) continue;
    s += sep + key + "=" + py::repr(self.attr(key.c_str())).cast<std::string>();
    sep = ", ";
  }
  return s + ")";
}

}  // namespace sillage::python
