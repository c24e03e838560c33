// Pointwise tube contractors (thesis 3.2.3): Ctc.contract (so CtcFunction,
// CtcCompo, ... too) gains the tube forms next to the box form:
//   c.contract(box)            -> the box, contracted in place (unchanged)
//   c.contract(x1, x2, ..., xn) (Tubes) -> bool, the tubes contracted in place
//   c.contract(tubevector)     -> bool
// Ctc is registered in bind_ctc.cpp; here its method "contract" is replaced
// by a dispatcher that hands boxes (and anything not a tube) to the original
// method, so its conversions and errors stay. A CtcFunction runs HC4 without
// virtual calls; other contractors are called once per slice and gate.
#include <vector>

#include "bindings.h"
#include "sillage/error.h"
#include "sillage/tube/tube_ctc.h"

namespace sillage::python {

namespace {

constexpr const char* kContractDoc =
    "contract(x) -> x: contracts the box x in place.\n"
    "contract(x1, ..., xn) -> bool: applies f(x1(t), ..., xn(t)) in y at every t to the Tubes (same\n"
    "TDomain, n = nb_vars()), every slice and every gate, in place; False if the tubes are (now) empty.\n"
    "contract(v) -> bool: the same with the components of the TubeVector v.";

}  // namespace

SILLAGE_BINDING(tube_ctc, "ctc", "tube") {
  py::object cls = m.attr("Ctc");
  py::object box_contract = py::getattr(cls, "contract");
  py::object tube_type = m.attr("Tube"), tv_type = m.attr("TubeVector");
  py::setattr(
      cls, "contract",
      py::cpp_function(
          [box_contract, tube_type, tv_type](const py::object& self, const py::args& args,
                                             const py::kwargs& kwargs) -> py::object {
            const std::size_t n = args.size();
            const bool tubes = n > 0 && kwargs.empty() &&
                               (py::isinstance(args[0], tube_type) || py::isinstance(args[0], tv_type));
            if (!tubes) return box_contract(self, *args, **kwargs);
            const Ctc& c = self.cast<const Ctc&>();
            // Only pure C++ work runs without the GIL (a Python contractor would take it per slice).
            const bool release = dynamic_cast<const CtcFunction*>(&c) != nullptr;
            const auto run = [&](auto& x) {
              if (!release) return contract(c, x);
              py::gil_scoped_release unlocked;
              return contract(c, x);
            };
            if (n == 1 && py::isinstance(args[0], tv_type)) return py::bool_(run(args[0].cast<TubeVector&>()));
            std::vector<Tube*> x(n);
            for (std::size_t i = 0; i < n; ++i) {
              if (!py::isinstance(args[i], tube_type)) {
                throw Error("Ctc.contract: argument " + std::to_string(i) +
                            " is not a Tube (pass n Tubes, one TubeVector or a box)");
              }
              x[i] = &args[i].cast<Tube&>();
            }
            return py::bool_(run(x));
          },
          py::name("contract"), py::is_method(cls), kContractDoc));
}

}  // namespace sillage::python
