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

// Name-once bindings (as coal's DEF_CLASS_FUNC): members and functions bound
// under their C++ names with their header comments as docstrings, each name
// written once. T is the class's own name, not an alias: the DOC macros are
// named after it.
//   py::class_<Tube, ...>(m, "Tube", DOC(Tube))
//       .SILLAGE_DEFS(Tube, volume, codomain)         // methods without arguments to name
//       .SILLAGE_DEF(Tube, is_subset, py::arg("y"))   // one method, extras after the name
//   py::class_<Options>(m, "Options", DOC(Options)).SILLAGE_FIELDS(Options, eps, budget);
//   m.SILLAGE_FN(tube_from_bounds, py::arg("tdomain"), py::arg("lb"), py::arg("ub"));
// SILLAGE_READONLY_FIELDS binds def_readonly, SILLAGE_PROPERTIES
// def_property_readonly, SILLAGE_DEF_STATIC def_static. Overloads
// (py::overload_cast, DOC(T, name, tag)), other Python names and what is
// Python-only stay written out.
#define SILLAGE_DEF(T, name, ...) def(#name, &T::name __VA_OPT__(, ) __VA_ARGS__, DOC(T, name))
#define SILLAGE_DEF_STATIC(T, name, ...) def_static(#name, &T::name __VA_OPT__(, ) __VA_ARGS__, DOC(T, name))
#define SILLAGE_FN(name, ...) def(#name, &name __VA_OPT__(, ) __VA_ARGS__, DOC(name))
#define SILLAGE_DEFS(T, ...) SILLAGE_EACH(SILLAGE_DEF, T, __VA_ARGS__)
#define SILLAGE_FIELDS(T, ...) SILLAGE_EACH(SILLAGE_FIELD_, T, __VA_ARGS__)
#define SILLAGE_READONLY_FIELDS(T, ...) SILLAGE_EACH(SILLAGE_READONLY_, T, __VA_ARGS__)
#define SILLAGE_PROPERTIES(T, ...) SILLAGE_EACH(SILLAGE_PROPERTY_, T, __VA_ARGS__)
#define SILLAGE_FIELD_(T, name) def_readwrite(#name, &T::name, DOC(T, name))
#define SILLAGE_READONLY_(T, name) def_readonly(#name, &T::name, DOC(T, name))
#define SILLAGE_PROPERTY_(T, name) def_property_readonly(#name, &T::name, DOC(T, name))
// SILLAGE_EACH(F, T, a, b, c) is F(T, a).F(T, b).F(T, c): the __VA_OPT__
// recursion of C++20, rescanned up to 256 times (names a list can hold).
#define SILLAGE_EACH(F, T, first, ...) F(T, first) __VA_OPT__(SILLAGE_EXPAND(SILLAGE_EACH_NEXT(F, T, __VA_ARGS__)))
#define SILLAGE_EACH_NEXT(F, T, a, ...) .F(T, a) __VA_OPT__(SILLAGE_EACH_AGAIN SILLAGE_PARENS(F, T, __VA_ARGS__))
#define SILLAGE_EACH_AGAIN() SILLAGE_EACH_NEXT
#define SILLAGE_PARENS ()
#define SILLAGE_EXPAND(...) SILLAGE_EXPAND3(SILLAGE_EXPAND3(SILLAGE_EXPAND3(SILLAGE_EXPAND3(__VA_ARGS__))))
#define SILLAGE_EXPAND3(...) SILLAGE_EXPAND2(SILLAGE_EXPAND2(SILLAGE_EXPAND2(SILLAGE_EXPAND2(__VA_ARGS__))))
#define SILLAGE_EXPAND2(...) SILLAGE_EXPAND1(SILLAGE_EXPAND1(SILLAGE_EXPAND1(SILLAGE_EXPAND1(__VA_ARGS__))))
#define SILLAGE_EXPAND1(...) __VA_ARGS__

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
