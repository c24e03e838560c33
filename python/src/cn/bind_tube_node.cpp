// sillage.TubeCtc: the Python face of TubeNode (cn/tube_node.h), to prototype
// a contractor on whole tubes in Python. A subclass overrides
// contract(self, domains): `domains` is the list given to
// ContractorNetwork.add (Tube, TubeVector, Interval, IntervalVector objects,
// the user's own), to contract in place; it returns None or True, or False
// when it proves that there is no solution. cn.add(MyCtc(), [x, v]) calls it
// until the fixed point, like any other contractor: each run is intersected
// with the domains before it (a prototype cannot enlarge a domain) and what
// shrank wakes the other contractors on those slices.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/cn/tube_node.h"
#include "sillage/error.h"

namespace sillage::python {

namespace {

class TubeCtc {
 public:
  virtual ~TubeCtc() = default;
  virtual py::object contract(const py::list& domains) const = 0;
};

class PyTubeCtc : public TubeCtc {
 public:
  py::object contract(const py::list& domains) const override {
    PYBIND11_OVERRIDE_PURE(py::object, TubeCtc, contract, domains);
  }
};

// What contract() returns to say where it found no solution: argument `arg`
// of the domains list (a Tube or TubeVector), its component, and a slice or
// a gate; the network's emptiness message then names that tube and time.
struct Emptied {
  std::size_t arg = 0, component = 0;
  std::optional<std::size_t> slice, gate;
};

// The atom of the node (numbered across its ranges, as run() does) that e names, for the
// domains list `items` (one range per Tube, per TubeVector component, per Interval or
// IntervalVector); Error saying what is wrong otherwise.
std::size_t emptied_atom(const Emptied& e, const py::list& items, const std::vector<AtomRange>& ranges,
                         const std::string& name) {
  const std::string where = name + ".contract returned Emptied(arg=" + std::to_string(e.arg) + "): ";
  if (e.arg >= items.size()) throw Error(where + "no such argument (" + std::to_string(items.size()) + " domains)");
  std::size_t range = 0;
  for (std::size_t i = 0; i < e.arg; ++i)
    range += py::isinstance<TubeVector>(items[i]) ? items[i].cast<const TubeVector&>().size() : 1;
  const py::handle h = items[e.arg];
  const bool vec = py::isinstance<TubeVector>(h);
  if (!vec && !py::isinstance<Tube>(h)) throw Error(where + "expected a Tube or TubeVector argument");
  const std::size_t n = vec ? h.cast<const TubeVector&>().size() : 1;
  if (e.component >= n) throw Error(where + "component " + std::to_string(e.component) + " out of range (" + std::to_string(n) + ")");
  range += e.component;
  if (range >= ranges.size() || e.slice.has_value() == e.gate.has_value())
    throw Error(where + "expected one of slice=k or gate=k");
  const std::size_t atom = e.slice ? 2 * *e.slice + 1 : 2 * *e.gate;
  if (atom >= ranges[range].count)
    throw Error(where + (e.slice ? "slice " + std::to_string(*e.slice) : "gate " + std::to_string(*e.gate)) +
                " out of range (" + std::to_string(ranges[range].count / 2) + " slices)");
  std::size_t k = atom;
  for (std::size_t g = 0; g < range; ++g) k += ranges[g].count;
  return k;
}

// A Python object held from C++: released with the GIL.
std::shared_ptr<py::object> keep(const py::handle& h) {
  return std::shared_ptr<py::object>(new py::object(py::reinterpret_borrow<py::object>(h)), [](py::object* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
}

// Runs the override on the whole domains: snapshot of every atom, the call
// (with the GIL), then every atom intersected with its former value and
// reported through TubeNode::changes.
class PyTubeNode : public TubeNode {
 public:
  PyTubeNode(std::string name, const std::vector<BoundDomain>& args, std::shared_ptr<py::object> ctc,
             std::shared_ptr<py::object> domains)
      : TubeNode(std::move(name), args), ctc_(std::move(ctc)), domains_(std::move(domains)) {}

  bool run(NodeRun& r) const override {
    std::vector<Interval> before;
    before.reserve(nb_atoms());
    for (const AtomRange& g : ranges()) {
      for (std::size_t a = 0; a < g.count; ++a) before.push_back(r.domains[g.domain]->atom(g.first + a));
    }
    bool ok = true;
    std::size_t emptied = kNoAtom;  // where contract() said it found no solution
    {
      py::gil_scoped_acquire gil;
      const py::object res = ctc_->attr("contract")(*domains_);
      if (py::isinstance<Emptied>(res)) {
        ok = false;
        emptied = emptied_atom(res.cast<Emptied>(), domains_->cast<py::list>(), ranges(), name());
      } else if (!res.is_none()) {
        if (!py::isinstance<py::bool_>(res)) {
          throw ArgumentTypeError(name() + ".contract must return None, True or False, not " +
                                  std::string(py::str(py::type::handle_of(res).attr("__name__"))));
        }
        ok = res.cast<bool>();
      }
    }
    for (const AtomRange& g : ranges()) {
      if (r.domains[g.domain]->layout_changed()) return true;  // the network reports it
    }
    std::size_t k = 0;
    for (std::size_t g = 0; g < ranges().size(); ++g) {
      Domain& d = *r.domains[ranges()[g].domain];
      const TubeChanges out = changes(r, g);
      for (std::size_t a = 0; a < ranges()[g].count; ++a, ++k) {
        const std::size_t i = ranges()[g].first + a;
        const Interval cur = d.atom(i);
        const Interval now = ok ? cur & before[k] : Interval::empty();  // False: no solution
        if (now != cur) d.set_atom(i, now);
        out.atom(a, before[k], now);
        if (now.is_empty() && ok && r.empty_at == kNoAtom) r.empty_at = k;
      }
    }
    if (!ok) r.empty_at = emptied;  // kNoAtom: False, no place given
    return ok && r.empty_at == kNoAtom;
  }

 private:
  std::shared_ptr<py::object> ctc_, domains_;
};

// The NetworkCtc that ContractorNetwork.add uses for a TubeCtc.
class PyTubeBinding : public NetworkCtc {
 public:
  PyTubeBinding(std::string name, std::shared_ptr<py::object> ctc, std::shared_ptr<py::object> domains)
      : name_(std::move(name)), ctc_(std::move(ctc)), domains_(std::move(domains)) {}
  std::string name() const override { return name_; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override {
    return std::make_shared<PyTubeNode>(name_, args, ctc_, domains_);
  }

 private:
  std::string name_;
  std::shared_ptr<py::object> ctc_, domains_;
};

}  // namespace

bool is_tube_ctc(const py::handle& h) { return py::isinstance<TubeCtc>(h); }

std::shared_ptr<const NetworkCtc> bind_tube_ctc(const py::handle& ctc, const py::list& domains) {
  std::string name = py::str(py::type::handle_of(ctc).attr("__name__"));
  if (py::hasattr(ctc, "name")) name = py::str(ctc.attr("name")());
  return std::make_shared<PyTubeBinding>(name, keep(ctc), keep(domains));
}

SILLAGE_BINDING(tube_node, "cn", "interval") {
  py::class_<TubeCtc, PyTubeCtc, std::shared_ptr<TubeCtc>>(
      m, "TubeCtc",
      "A contractor on whole tubes written in Python (the face of the C++ TubeNode).\n\n"
      "Subclass it and override contract(self, domains): `domains` is the list given to\n"
      "ContractorNetwork.add(ctc, domains) (your Tube, TubeVector, Interval, IntervalVector objects),\n"
      "contracted in place. Return None or True, or False when there is no solution. The network\n"
      "calls it until the fixed point; each call is intersected with the domains before it, and the\n"
      "slices that shrank wake the other contractors. Optional: name(self) for the reports.")
      .def(py::init<>(), "A contractor to subclass: call super().__init__() in your __init__.")
      .def("__repr__",
           [](const py::object& self) {
             return "<" + py::str(py::type::of(self).attr("__name__")).cast<std::string>() + " (TubeCtc)>";
           })
      .def("contract", &TubeCtc::contract, py::arg("domains"),
           "Contracts the domains in place; returns None, True, False for 'no solution', or "
           "Emptied(arg, slice=k) / Emptied(arg, gate=k) for 'no solution, found there'.");
  py::class_<Emptied>(m, "Emptied",
                      "What TubeCtc.contract returns when it proves that there is no solution and knows where:\n"
                      "the argument `arg` of its domains list (a Tube or TubeVector), its `component`, and the\n"
                      "slice or the gate. The network's emptiness message then names that tube and time instead of\n"
                      "its first atom.")
      .def(py::init([](std::size_t arg, std::optional<std::size_t> slice, std::optional<std::size_t> gate,
                       std::size_t component) { return Emptied{arg, component, slice, gate}; }),
           py::arg("arg"), py::arg("slice") = py::none(), py::arg("gate") = py::none(), py::arg("component") = 0,
           "Emptied(arg, slice=k) or Emptied(arg, gate=k), with component=i for a TubeVector.")
      .def_readonly("arg", &Emptied::arg, "The index of the domain in the list given to contract().")
      .def_readonly("component", &Emptied::component, "The component of a TubeVector (0 for a Tube).")
      .def_readonly("slice", &Emptied::slice, "The slice where no solution was found, or None.")
      .def_readonly("gate", &Emptied::gate, "The gate where no solution was found, or None.")
      .def("__repr__", [](const Emptied& e) {
        return "Emptied(" + std::to_string(e.arg) + (e.slice ? ", slice=" + std::to_string(*e.slice) : "") +
               (e.gate ? ", gate=" + std::to_string(*e.gate) : "") +
               (e.component ? ", component=" + std::to_string(e.component) : "") + ")";
      });
}

}  // namespace sillage::python
