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
#include <string>
#include <vector>

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
    {
      py::gil_scoped_acquire gil;
      const py::object res = ctc_->attr("contract")(*domains_);
      if (!res.is_none()) {
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
           "Contracts the domains in place; returns None, True, or False for 'no solution'.");
}

}  // namespace sillage::python
