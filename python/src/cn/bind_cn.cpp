// ContractorNetwork. Domains are the user's own Interval / IntervalVector /
// Tube / TubeVector objects (shared with C++ through their std::shared_ptr holders), contracted
// in place; DomainRef.component(x, i) / DomainRef.subvector(x, i, j) bind parts
// of a box.
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "bindings.h"
#include "interruptible.h"
#include "sillage/cn/contractor_network.h"

namespace sillage::python {

std::shared_ptr<const Ctc> hold_ctc(const py::handle& h);  // bind_ctc.cpp
bool is_tube_ctc(const py::handle& h);                     // bind_tube_node.cpp
std::shared_ptr<const NetworkCtc> bind_tube_ctc(const py::handle& ctc, const py::list& domains);

namespace {

DomainRef to_domain_ref(const py::handle& h, std::size_t index) {
  if (py::isinstance<Interval>(h)) return DomainRef(h.cast<std::shared_ptr<Interval>>());
  if (py::isinstance<IntervalVector>(h)) return DomainRef(h.cast<std::shared_ptr<IntervalVector>>());
  if (py::isinstance<Tube>(h)) return DomainRef(h.cast<std::shared_ptr<Tube>>());
  if (py::isinstance<TubeVector>(h)) return DomainRef(h.cast<std::shared_ptr<TubeVector>>());
  if (py::isinstance<DomainRef>(h)) return h.cast<DomainRef>();
  throw Error("ContractorNetwork.add: domain " + std::to_string(index) + " is a " +
              std::string(py::str(py::type::handle_of(h).attr("__name__"))) +
              ", expected Interval, IntervalVector, Tube, TubeVector or DomainRef");
}

}  // namespace

void init_cn(py::module_& m) {
  py::class_<NetworkCtc, std::shared_ptr<NetworkCtc>>(
      m, "NetworkCtc", "A contractor on whole tubes that a ContractorNetwork binds (CtcDeriv, CtcEval).")
      .def("name", &NetworkCtc::name, "The class name, e.g. 'CtcEval'.")
      .def("__repr__", [](const NetworkCtc& c) { return "<" + c.name() + ">"; });

  py::class_<DomainRef>(m, "DomainRef", "A part of a box given to ContractorNetwork.add.")
      .def("__repr__",
           [](const DomainRef& r) {
             return "DomainRef(first=" + std::to_string(r.first()) + ", count=" + std::to_string(r.count()) + ")";
           })
      .def_static("component", py::overload_cast<std::shared_ptr<IntervalVector>, std::size_t>(&DomainRef::component),
                  py::arg("x"), py::arg("i"), "Component i of the box x, live: the network contracts x[i] itself.")
      .def_static("component", py::overload_cast<std::shared_ptr<TubeVector>, std::size_t>(&DomainRef::component),
                  py::arg("x"), py::arg("i"), "Component i of a tube vector, live.")
      .def_static("subvector", &DomainRef::subvector, py::arg("x"), py::arg("i"), py::arg("j"),
                  "Components i to j (inclusive) of the box x, live.")
      .def("first", &DomainRef::first, "Index of the first component referred to.")
      .def("count", &DomainRef::count, "Number of components referred to.");

  py::class_<ContractStats>(m, "ContractStats",
                            "What contract() did. An empty network is an answer (no solution), explained by\n"
                            "emptiness and the empty_* fields.")
      .def_readonly("iterations", &ContractStats::iterations, "Rounds of the propagation queue.")
      .def_readonly("contractor_calls", &ContractStats::contractor_calls, "Calls of Ctc.contract (node runs).")
      .def_readonly("time", &ContractStats::time, "Wall-clock seconds.")
      .def_readonly("empty", &ContractStats::empty, "A domain became (or was) empty: no solution.")
      .def_readonly("empty_domain", &ContractStats::empty_domain, "Which one, e.g. 'domain 2 (Interval)'.")
      .def_readonly("emptiness", &ContractStats::emptiness,
                    "Why, e.g. \"CtcEval emptied tube 'x' at slice 412 [41.2, 41.3] for t in [...]\"; '' if not empty.")
      .def_readonly("empty_contractor", &ContractStats::empty_contractor,
                    "The contractor that emptied it (e.g. 'CtcDeriv'); '' if it was empty on input.")
      .def_readonly("empty_node", &ContractStats::empty_node,
                    "Index (in add() order) of the node that emptied it; 2**64 - 1 if it was empty on input.")
      .def_readonly("empty_domain_index", &ContractStats::empty_domain_index,
                    "The emptied domain's index in the network.")
      .def_readonly("empty_domain_name", &ContractStats::empty_domain_name, "Its name (set_name), '' if none.")
      .def_readonly("empty_atom", &ContractStats::empty_atom,
                    "'slice', 'gate', 'component' or '' (the whole domain).")
      .def_readonly("empty_atom_index", &ContractStats::empty_atom_index,
                    "Index of the slice, gate or component that became empty.")
      .def_readonly("empty_time", &ContractStats::empty_time, "Time of the slice or gate (empty otherwise).")
      .def("__repr__", [](const ContractStats& s) {
        return "ContractStats(iterations=" + std::to_string(s.iterations) +
               ", contractor_calls=" + std::to_string(s.contractor_calls) + ", time=" + std::to_string(s.time) +
               ", empty=" + (s.empty ? "True, emptiness='" + s.emptiness + "'" : std::string("False")) + ")";
      });

  py::class_<ContractorNetwork>(m, "ContractorNetwork",
                                "Variables (domains) linked by contractors, propagated to a fixed point (thesis "
                                "2.3.1). Domains are the caller's own objects (Interval, IntervalVector, Tube, "
                                "TubeVector or a DomainRef part), contracted in place. A contractor on a tube argument "
                                "is applied at every time; CtcDeriv and CtcEval act on whole tubes.")
      .def("__repr__",
           [](const ContractorNetwork& cn) {
             return "ContractorNetwork(" + std::to_string(cn.nb_ctc()) + " contractors, " + std::to_string(cn.nb_dom()) +
                    " domains)";
           })
      .def(py::init<>(), "An empty network.")
      .def("create_dom", py::overload_cast<const Interval&, const std::string&>(&ContractorNetwork::create_dom),
           py::arg("x"), py::arg("name") = "", "A new domain (a copy of x), optionally named.")
      .def("create_dom",
           py::overload_cast<const IntervalVector&, const std::string&>(&ContractorNetwork::create_dom), py::arg("x"),
           py::arg("name") = "", "A new box domain (a copy of x), optionally named.")
      .def(
          "set_name",
          [](ContractorNetwork& cn, const py::object& domain, const std::string& name) {
            cn.set_name(to_domain_ref(domain, 0), name);
          },
          py::arg("domain"), py::arg("name"),
          "Names a domain for the reports (stats.emptiness); a TubeVector's components become name[i].")
      .def("domain_name", &ContractorNetwork::domain_name, py::arg("d"), "The name of domain number d ('' if none).")
      .def(
          "add",
          [](ContractorNetwork& cn, const py::object& ctc, const py::iterable& domains) {
            const py::list items(domains);
            std::vector<DomainRef> refs;
            for (const auto& h : items) refs.push_back(to_domain_ref(h, refs.size()));
            if (is_tube_ctc(ctc)) {
              cn.add(bind_tube_ctc(ctc, items), refs);
            } else if (py::isinstance<NetworkCtc>(ctc)) {
              cn.add(std::shared_ptr<const NetworkCtc>(ctc.cast<std::shared_ptr<NetworkCtc>>()), refs);
            } else {
              cn.add(hold_ctc(ctc), refs);
            }
          },
          py::arg("ctc"), py::arg("domains"),
          "Adds the contractor ctc (a Ctc, a NetworkCtc or a TubeCtc subclass) on the concatenation of the domains "
          "(Interval, IntervalVector, Tube, TubeVector, DomainRef); their sizes must add up to ctc.nb_vars() "
          "(DimensionError otherwise).")
      .def(
          "contract",
          [](ContractorNetwork& cn) {
            // Without the GIL, on a worker, so that Ctrl-C stops it (interruptible.h).
            const Budget user = cn.budget();
            return run_interruptible(user.cancel, [&cn, &user](const CancelToken& token) {
              struct Restore {
                ContractorNetwork& cn;
                const Budget& b;
                ~Restore() { cn.set_budget(b); }
              } restore{cn, user};
              cn.set_budget(with_token(user, token));
              return cn.contract();
            });
          },
          "Propagates to the fixed point; the domains are contracted in place. Returns ContractStats;\n"
          "stats.empty means no solution, and stats.emptiness says which contractor emptied which domain.\n"
          "Ctrl-C raises KeyboardInterrupt; budget() limits it (BudgetExceeded, Cancelled).")
      .def("nb_ctc", &ContractorNetwork::nb_ctc, "Number of contractors added.")
      .def("nb_dom", &ContractorNetwork::nb_dom, "Number of domains known to the network.")
      .def("ratio", &ContractorNetwork::ratio,
           "The shrink ratio above which a contracted atom wakes its other contractors (default 0.01).")
      .def("budget", &ContractorNetwork::budget,
           "The limits of contract(): max_boxes counts contractor calls, max_seconds the time, cancel a CancelToken.")
      .def("set_budget", &ContractorNetwork::set_budget, py::arg("budget"),
           "Sets budget(); contract() then raises BudgetExceeded past it (the domains stay enclosures).")
      .def("set_ratio", &ContractorNetwork::set_ratio, py::arg("ratio"),
           "Sets ratio(): a component that shrank by more than ratio wakes the contractors acting on it.");
}

}  // namespace sillage::python
