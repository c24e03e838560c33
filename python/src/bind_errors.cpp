#include <string>

#include "bindings.h"
#include "sillage/budget.h"
#include "sillage/error.h"
#include "sillage/text_utf8.h"

namespace sillage::python {

namespace {

// A Python exception class named `name` in m, with the given bases.
py::handle new_exception(py::module_& m, const char* name, const py::tuple& bases, const char* doc) {
  const std::string full = std::string(PyModule_GetName(m.ptr())) + "." + name;
  py::object type =
      py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(full.c_str(), doc, bases.ptr(), nullptr));
  if (!type) throw py::error_already_set();
  m.attr(name) = type;
  return type.release();  // one reference kept for the translator, for the life of the process
}

// Raises `type` with the message decoded as UTF-8, invalid bytes replaced:
// a message that does not decode must not become an empty exception.
void raise(py::handle type, const char* what) {
  const std::string message = detail::valid_utf8(what);
  PyErr_SetString(type.ptr(), message.c_str());
}

}  // namespace

// sillage::Error becomes sillage.Error (a ValueError) and its subclasses
// subclasses of it; ArgumentTypeError and OutOfRangeError are also a
// TypeError and an IndexError, BudgetExceeded a sillage.Error, Cancelled a
// KeyboardInterrupt (not an Error: the input was fine). Other standard
// exceptions map as pybind11 maps them; every message is made valid UTF-8.
SILLAGE_BINDING(errors) {
  static py::handle error, dimension, parse, type, range, budget, cancelled;
  error = new_exception(m, "Error", py::make_tuple(py::handle(PyExc_ValueError)),
                        "Invalid input (a ValueError); the message says what is wrong and where.\n"
                        "An empty set is a result, not an error.");
  dimension = new_exception(m, "DimensionError", py::make_tuple(error),
                            "Sizes that do not agree (box dimensions, matrix shapes, argument counts).");
  parse = new_exception(m, "ParseError", py::make_tuple(error),
                        "A text that cannot be parsed (expressions, data files).");
  type = new_exception(m, "ArgumentTypeError", py::make_tuple(error, py::handle(PyExc_TypeError)),
                       "A value of the wrong type where sillage expected another (a callable returning a str\n"
                       "instead of a box, a lambda instead of a contractor); also a TypeError.");
  range = new_exception(m, "OutOfRangeError", py::make_tuple(error, py::handle(PyExc_IndexError)),
                        "An index or a time out of the valid range (a row, a slice, a component); also an IndexError.");
  budget = new_exception(m, "BudgetExceeded", py::make_tuple(error),
                         "A computation went past its Budget (boxes, bytes or seconds).");
  cancelled = new_exception(m, "Cancelled", py::make_tuple(py::handle(PyExc_KeyboardInterrupt)),
                            "A computation stopped by its CancelToken or by Ctrl-C (a KeyboardInterrupt, not an "
                            "Error).");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const DimensionError& e) {
      raise(dimension, e.what());
    } catch (const ParseError& e) {
      raise(parse, e.what());
    } catch (const ArgumentTypeError& e) {
      raise(type, e.what());
    } catch (const OutOfRangeError& e) {
      raise(range, e.what());
    } catch (const BudgetExceeded& e) {
      raise(budget, e.what());
    } catch (const Error& e) {
      raise(error, e.what());
    } catch (const Cancelled& e) {
      raise(cancelled, e.what());
    } catch (const py::error_already_set&) {
      throw;  // pybind11's own exceptions: its translator knows them
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "out of memory");
    } catch (const std::out_of_range& e) {  // pybind11's mapping of the standard exceptions, made UTF-8 safe
      raise(PyExc_IndexError, e.what());
    } catch (const std::overflow_error& e) {
      raise(PyExc_OverflowError, e.what());
    } catch (const std::range_error& e) {
      raise(PyExc_ValueError, e.what());
    } catch (const std::logic_error& e) {
      raise(PyExc_ValueError, e.what());
    } catch (const std::exception& e) {
      raise(PyExc_RuntimeError, e.what());
    }
  });
}

}  // namespace sillage::python
