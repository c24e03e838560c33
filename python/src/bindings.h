#pragma once
// What the binding files share: the registration of a binding file
// (SILLAGE_BINDING, below) and helpers. The files live in
// python/src/<layer>/bind_<name>.cpp, compiled into the module itself (so
// that the linker keeps their static registrars).
#include <pybind11/pybind11.h>

#include <initializer_list>
#include <string>
#include <vector>

namespace sillage {
class Interval;
}

namespace sillage::python {
namespace py = pybind11;

// A Python int (any size; numpy integers too) as the tightest interval:
// itself when it is a double, else the two doubles around it (bind_interval.cpp).
bool is_int(const py::handle& h);
Interval int_enclosure(const py::handle& h);

// True when h is a numpy array. numpy is optional: while it is not imported,
// no object can be an array, and asking pybind11 would import it (and fail
// where it is not installed).
bool is_ndarray(const py::handle& h);

// copy(), __copy__ and __deepcopy__ of a value type: a C++ copy.
template <class Class>
void def_copy(Class& cls) {
  using T = typename Class::type;
  cls.def("copy", [](const T& x) { return T(x); }, "An independent copy (copy.copy and copy.deepcopy give the same).")
      .def("__copy__", [](const T& x) { return T(x); })
      .def("__deepcopy__", [](const T& x, py::dict) { return T(x); });
}
// A __repr__ "Name(field=value, ...)" over the class's properties (its
// def_readwrite / def_readonly fields), for option and result structs.
std::string fields_repr(const py::object& self);

// The GIL released during the call, for a C++ function that touches no Python
// object: pybind11 converts the arguments before and the result after, with
// the GIL held. Not for a computation Ctrl-C must stop (interruptible.h).
//   .def("contract", &CtcSecondDeriv::contract, py::arg("x"), py::arg("a"), nogil, DOC(...))
inline constexpr py::call_guard<py::gil_scoped_release> nogil{};

// Each binding file registers itself, declaratively (module.cpp calls them all):
//
//   SILLAGE_BINDING(tube, "expr", "interval", "tdomain", "trajectory") {
//     py::class_<Tube, std::shared_ptr<Tube>>(m, "Tube") ...;
//   }
//
// The first argument names the binding (the file's bind_<name>.cpp); the
// strings after it name the bindings it comes after: those whose classes it
// uses (as a base class, an argument or return type, a default value, or
// m.attr("...")) and those whose module functions or methods it adds
// overloads to (pybind11 tries overloads in the order they were bound). The
// module calls every registered binding once, each after the ones it names. A
// name that no binding registers, a name registered twice or a cycle is an
// ImportError naming the binding. tests/python/test_bindings_registry.py
// checks the declarations against the classes each file names.
struct Binding {
  std::string name;
  std::vector<std::string> after;
  void (*init)(py::module_&);
  std::string file;  // python/src/...
};
// Every binding of the module, in the order of the static initializers.
std::vector<Binding>& binding_registry();
// The bindings in an order where each comes after the ones it names (depth
// first, in name order: the same order whatever the link order);
// std::runtime_error on an unknown name, a name registered twice or a cycle.
std::vector<const Binding*> binding_order(const std::vector<Binding>& bindings);

// Adds a binding to the registry (a static object of SILLAGE_BINDING).
struct BindingRegistrar {
  BindingRegistrar(const char* name, std::initializer_list<const char*> after, void (*init)(py::module_&),
                   const char* file);
};

#define SILLAGE_BINDING(name, ...)                                                   \
  static void sillage_binding_##name(::pybind11::module_& m);                        \
  static const ::sillage::python::BindingRegistrar sillage_binding_registrar_##name( \
      #name, {__VA_ARGS__}, &sillage_binding_##name, __FILE__);                      \
  static void sillage_binding_##name(::pybind11::module_& m)

}  // namespace sillage::python
