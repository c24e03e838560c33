// Contractors and separators. Ctc and Sep can be subclassed in Python
// (override contract(self, x) / separate(self, x_in, x_out)). contract and
// separate act in place on the IntervalVector objects given, and return them.
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "arg_checks.h"
#include "bindings.h"
#include "docstrings.h"
#include "sillage/ctc/ctc_algebra.h"
#include "sillage/ctc/ctc_binary.h"
#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_unary.h"
#include "sillage/ctc/definition_check.h"
#include "sillage/ctc/sep_algebra.h"
#include "sillage/ctc/sep_ctc_pair.h"
#include "sillage/ctc/sep_function.h"

namespace sillage::python {

namespace {

// Python subclasses of Ctc. The override gets a fresh IntervalVector (so a
// Python reference kept to it can never dangle), contracts it in place or
// returns a box; the result is intersected with x (contraction guaranteed).
class PyCtc : public Ctc {
 public:
  using Ctc::Ctc;
  void contract(IntervalVector& x) const override {
    py::gil_scoped_acquire gil;
    const py::function f = py::get_override(static_cast<const Ctc*>(this), "contract");
    if (!f) throw Error(name() + ".contract is not implemented");
    const auto box = std::make_shared<IntervalVector>(x);
    const py::object r = f(box);
    const IntervalVector res = r.is_none() ? *box : r.cast<IntervalVector>();
    if (res.size() != x.size()) {
      throw DimensionError(name() + ".contract returned a box of size " + std::to_string(res.size()) +
                           ", expected " + std::to_string(x.size()));
    }
    x &= res;
  }
  std::string name() const override {
    py::gil_scoped_acquire gil;
    const py::function f = py::get_override(static_cast<const Ctc*>(this), "name");
    if (f) return f().cast<std::string>();
    return py::str(py::type::handle_of(py::cast(this, py::return_value_policy::reference)).attr("__name__"));
  }
};

class PySep : public Sep {
 public:
  using Sep::Sep;
  void separate(IntervalVector& x_in, IntervalVector& x_out) const override {
    py::gil_scoped_acquire gil;
    const py::function f = py::get_override(static_cast<const Sep*>(this), "separate");
    if (!f) throw Error(name() + ".separate is not implemented");
    const auto in = std::make_shared<IntervalVector>(x_in), out = std::make_shared<IntervalVector>(x_out);
    f(in, out);  // in place
    if (in->size() != x_in.size() || out->size() != x_out.size()) {
      throw DimensionError(name() + ".separate resized its boxes");
    }
    x_in &= *in;
    x_out &= *out;
  }
  std::string name() const override {
    py::gil_scoped_acquire gil;
    return py::str(py::type::handle_of(py::cast(this, py::return_value_policy::reference)).attr("__name__"));
  }
};

// A shared pointer that also keeps the Python object alive: a Python subclass
// must outlive every C++ holder, or its overrides would vanish.
template <class T>
std::shared_ptr<const T> hold(const py::handle& h, const char* what) {
  if (h.is_none()) throw Error(std::string(what) + " is None");
  if (!py::isinstance<T>(h)) {  // a lambda, a string...: say what was expected
    const std::string expected = py::str(py::type::of<T>().attr("__name__"));
    throw ArgumentTypeError(std::string(what) + ": expected a sillage." + expected + " (or a subclass), got " +
                            type_name(h));
  }
  const auto p = h.cast<std::shared_ptr<T>>();
  auto* keep = new py::object(py::reinterpret_borrow<py::object>(h));
  return std::shared_ptr<const T>(p.get(), [keep](const T*) {
    py::gil_scoped_acquire gil;
    delete keep;
  });
}

template <class T>
std::vector<std::shared_ptr<const T>> hold_list(const py::iterable& list, const char* what) {
  std::vector<std::shared_ptr<const T>> v;
  for (const auto& h : list) v.push_back(hold<T>(h, what));
  return v;
}

}  // namespace

// Also used by bind_cn.cpp.
std::shared_ptr<const Ctc> hold_ctc(const py::handle& h) { return hold<Ctc>(h, "contractor"); }

SILLAGE_BINDING(ctc, "expr", "interval") {
  py::class_<Ctc, PyCtc, std::shared_ptr<Ctc>> ctc(m, "Ctc", DOC(Ctc));
  ctc.def(py::init<std::size_t>(), py::arg("nb_vars"),
           "A contractor on nb_vars variables (for a Python subclass, which overrides contract).")
      .def(
          "contract",
          [](const Ctc& c, const std::shared_ptr<IntervalVector>& x) {
            if (!x) throw Error("contract: the box is None");
            c.contract(*x);
            return x;
          },
          py::arg("x"), DOC(Ctc, contract))
      .SILLAGE_DEFS(Ctc, nb_vars, name, describe)
      .def("__repr__", [](const Ctc& c) { return "<" + c.name() + " on " + std::to_string(c.nb_vars()) + " variables>"; });

  py::class_<CtcBox, Ctc, std::shared_ptr<CtcBox>>(m, "CtcBox", DOC(CtcBox))
      .def(py::init<const IntervalVector&>(), py::arg("box"), DOC(CtcBox, CtcBox))
      .SILLAGE_DEF(CtcBox, box);
  py::class_<CtcBinary, Ctc, std::shared_ptr<CtcBinary>>(m, "CtcBinary",
                                                         DOC(CtcBinary))
      .def(py::init<const std::string&>(), py::arg("op"),
           DOC(CtcBinary, CtcBinary, string));
  py::class_<CtcAdd, CtcBinary, std::shared_ptr<CtcAdd>>(m, "CtcAdd",
      DOC(CtcAdd))
      .def(py::init<>(), DOC(CtcAdd, CtcAdd));
  py::class_<CtcSub, CtcBinary, std::shared_ptr<CtcSub>>(m, "CtcSub",
      DOC(CtcSub))
      .def(py::init<>(), DOC(CtcSub, CtcSub));
  py::class_<CtcMul, CtcBinary, std::shared_ptr<CtcMul>>(m, "CtcMul",
      DOC(CtcMul))
      .def(py::init<>(), DOC(CtcMul, CtcMul));
  py::class_<CtcDiv, CtcBinary, std::shared_ptr<CtcDiv>>(m, "CtcDiv",
      DOC(CtcDiv))
      .def(py::init<>(), DOC(CtcDiv, CtcDiv));
  py::class_<CtcUnary, Ctc, std::shared_ptr<CtcUnary>>(m, "CtcUnary",
                                                       DOC(CtcUnary))
      .def(py::init<const std::string&, int>(), py::arg("op"), py::arg("n") = 0,
           DOC(CtcUnary, CtcUnary, string_int));
  py::class_<CtcFunction, Ctc, std::shared_ptr<CtcFunction>>(m, "CtcFunction",
      DOC(CtcFunction))
      .def(py::init<const Function&, const IntervalVector&>(), py::arg("f"), py::arg("y"),
           DOC(CtcFunction, CtcFunction, Function_IntervalVector))
      .def(py::init<const Function&, const Interval&>(), py::arg("f"), py::arg("y"),
           DOC(CtcFunction, CtcFunction, Function_Interval))
      .def(py::init<const Function&>(), py::arg("f"), DOC(CtcFunction, CtcFunction, Function))
      .SILLAGE_DEFS(CtcFunction, function, image);

  py::class_<DefinitionCheck>(m, "DefinitionCheck", R"doc(
Proves that a Function is defined at every point of a box (set-based evaluation
silently ignores points where sqrt, log, /, ... are undefined).)doc")
      .def(py::init<const Function&>(), py::arg("f"),
           DOC(DefinitionCheck, DefinitionCheck))
      .def("__repr__",
           [](const DefinitionCheck& d) {
             return std::string("DefinitionCheck(total=") + (d.is_total() ? "True" : "False") + ")";
           })
      .SILLAGE_DEF(DefinitionCheck, defined_on, py::arg("x"))
      .SILLAGE_DEF(DefinitionCheck, is_total);

  const auto list_ctor = [](auto tag) {
    using T = typename decltype(tag)::type;
    return py::init([](const py::iterable& list) { return std::make_shared<T>(hold_list<Ctc>(list, "contractor")); });
  };
  py::class_<CtcInter, Ctc, std::shared_ptr<CtcInter>>(m, "CtcInter",
                                                       DOC(CtcInter))
      .def(list_ctor(std::type_identity<CtcInter>{}), py::arg("list"),
           "The intersection of a non-empty list of contractors on the same variables (else Error / DimensionError).");
  py::class_<CtcUnion, Ctc, std::shared_ptr<CtcUnion>>(m, "CtcUnion",
                                                       DOC(CtcUnion))
      .def(list_ctor(std::type_identity<CtcUnion>{}), py::arg("list"),
           "The union of a non-empty list of contractors on the same variables (else Error / DimensionError).");
  // After CtcInter and CtcUnion, so that the signatures name them.
  ctc.def("__and__",
          [](const py::object& a, const py::object& b) {
            return std::make_shared<CtcInter>(std::vector<CtcPtr>{hold_ctc(a), hold_ctc(b)});
          })
      .def("__or__", [](const py::object& a, const py::object& b) {
        return std::make_shared<CtcUnion>(std::vector<CtcPtr>{hold_ctc(a), hold_ctc(b)});
      });
  py::class_<CtcCompo, Ctc, std::shared_ptr<CtcCompo>>(m, "CtcCompo",
                                                       "Applies the contractors of the list in order, first to last.")
      .def(list_ctor(std::type_identity<CtcCompo>{}), py::arg("list"),
           "Cn o ... o C1 for the list [C1, ..., Cn] on the same variables.");
  py::class_<CtcFixPoint, Ctc, std::shared_ptr<CtcFixPoint>>(m, "CtcFixPoint",
      DOC(CtcFixPoint))
      .def(py::init([](const py::object& c, double ratio) { return std::make_shared<CtcFixPoint>(hold_ctc(c), ratio); }),
           py::arg("ctc"), py::arg("ratio") = 0.01,
           "Iterates ctc; 0 <= ratio < 1 (else Error), ratio = 0 iterates until nothing changes at all.")
      .SILLAGE_DEF(CtcFixPoint, ratio);

  // ---- separators ----
  py::class_<Sep, PySep, std::shared_ptr<Sep>> sep(m, "Sep", DOC(Sep));
  sep.def(py::init<std::size_t>(), py::arg("nb_vars"),
           "A separator on nb_vars variables (for a Python subclass, which overrides separate).")
      .def(
          "separate",
          [](const Sep& s, const std::shared_ptr<IntervalVector>& x_in, const std::shared_ptr<IntervalVector>& x_out) {
            if (!x_in || !x_out) throw Error("separate: a box is None");
            s.separate(*x_in, *x_out);
            return py::make_tuple(x_in, x_out);
          },
          py::arg("x_in"), py::arg("x_out"), DOC(Sep, separate))
      .SILLAGE_DEFS(Sep, nb_vars, name)
      .def("__repr__", [](const Sep& s) { return "<" + s.name() + " on " + std::to_string(s.nb_vars()) + " variables>"; });

  py::class_<SepCtcPair, Sep, std::shared_ptr<SepCtcPair>>(m, "SepCtcPair",
                                                           DOC(SepCtcPair))
      .def(py::init([](const py::object& in, const py::object& out) {
             return std::make_shared<SepCtcPair>(hold_ctc(in), hold_ctc(out));
           }),
           py::arg("ctc_in"), py::arg("ctc_out"), "The separator (ctc_in, ctc_out), both on the same variables.");
  py::class_<SepFunction, Sep, std::shared_ptr<SepFunction>>(m, "SepFunction",
      DOC(SepFunction))
      .def(py::init<const Function&, const IntervalVector&>(), py::arg("f"), py::arg("y"),
           DOC(SepFunction, SepFunction, Function_IntervalVector))
      .def(py::init<const Function&, const Interval&>(), py::arg("f"), py::arg("y"),
           DOC(SepFunction, SepFunction, Function_Interval));
  py::class_<SepInter, Sep, std::shared_ptr<SepInter>>(m, "SepInter",
                                                       DOC(SepInter))
      .def(py::init([](const py::iterable& l) { return std::make_shared<SepInter>(hold_list<Sep>(l, "separator")); }),
           py::arg("list"), "The intersection of a non-empty list of separators.");
  py::class_<SepUnion, Sep, std::shared_ptr<SepUnion>>(m, "SepUnion",
                                                       DOC(SepUnion))
      .def(py::init([](const py::iterable& l) { return std::make_shared<SepUnion>(hold_list<Sep>(l, "separator")); }),
           py::arg("list"), "The union of a non-empty list of separators.");
  py::class_<SepNot, Sep, std::shared_ptr<SepNot>>(m, "SepNot",
                                                   DOC(SepNot))
      .def(py::init([](const py::object& s) { return std::make_shared<SepNot>(hold<Sep>(s, "separator")); }),
           py::arg("sep"), "The complement of the separator sep.");
  // After SepInter, SepUnion and SepNot, so that the signatures name them.
  sep.def("__and__",
          [](const py::object& a, const py::object& b) {
            return std::make_shared<SepInter>(
                std::vector<SepPtr>{hold<Sep>(a, "separator"), hold<Sep>(b, "separator")});
          })
      .def("__or__",
           [](const py::object& a, const py::object& b) {
             return std::make_shared<SepUnion>(
                 std::vector<SepPtr>{hold<Sep>(a, "separator"), hold<Sep>(b, "separator")});
           })
      .def("__invert__", [](const py::object& a) { return std::make_shared<SepNot>(hold<Sep>(a, "separator")); });
}

}  // namespace sillage::python
