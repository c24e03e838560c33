// ContractorNetwork. Domains are the user's own Interval / IntervalVector /
// Tube / TubeVector objects (shared with C++ through their std::shared_ptr holders), contracted
// in place; DomainRef.component(x, i) / DomainRef.subvector(x, i, j) bind parts
// of a box.
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "bindings.h"
#include "docstrings.h"
#include "interruptible.h"
#include "sillage/cn/contractor_network.h"

namespace sillage::python {

std::shared_ptr<const Ctc> hold_ctc(const py::handle& h);  // bind_ctc.cpp
bool is_tube_ctc(const py::handle& h);                     // bind_tube_node.cpp
std::shared_ptr<const NetworkCtc> bind_tube_ctc(const py::handle& ctc, const py::list& domains);

// A Python domain (Interval, IntervalVector, Tube, TubeVector, DomainRef) as
// a DomainRef; `index` names it in the error (bind_online.cpp uses it too).
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

namespace {

// cn.contract() or cn.contract_run() without the GIL, on a worker, so that
// Ctrl-C stops it (interruptible.h); the user's budget is restored after.
ContractStats interruptible(ContractorNetwork& cn, ContractStats (ContractorNetwork::*run)()) {
  const Budget user = cn.budget();
  return run_interruptible(user.cancel, [&cn, &user, run](const CancelToken& token) {
    struct Restore {
      ContractorNetwork& cn;
      const Budget& b;
      ~Restore() { cn.set_budget(b); }
    } restore{cn, user};
    cn.set_budget(with_token(user, token));
    return (cn.*run)();
  });
}

}  // namespace

SILLAGE_BINDING(cn, "budget", "ctc", "interval", "tube") {
  py::class_<NetworkCtc, std::shared_ptr<NetworkCtc>>(
      m, "NetworkCtc", DOC(NetworkCtc))
      .def("name", &NetworkCtc::name, DOC(NetworkCtc, name))
      .def("__repr__", [](const NetworkCtc& c) { return "<" + c.name() + ">"; });

  py::class_<DomainRef>(m, "DomainRef", DOC(DomainRef))
      .def("__repr__",
           [](const DomainRef& r) {
             return "DomainRef(first=" + std::to_string(r.first()) + ", count=" + std::to_string(r.count()) + ")";
           })
      .def_static("component", py::overload_cast<std::shared_ptr<IntervalVector>, std::size_t>(&DomainRef::component),
                  py::arg("x"), py::arg("i"), DOC(DomainRef, component, IntervalVector_size_t))
      .def_static("component", py::overload_cast<std::shared_ptr<TubeVector>, std::size_t>(&DomainRef::component),
                  py::arg("x"), py::arg("i"), DOC(DomainRef, component, TubeVector_size_t))
      .def_static("subvector", &DomainRef::subvector, py::arg("x"), py::arg("i"), py::arg("j"),
                  DOC(DomainRef, subvector))
      .def("first", &DomainRef::first, DOC(DomainRef, first))
      .def("count", &DomainRef::count, DOC(DomainRef, count));

  py::class_<ContractStats>(m, "ContractStats",
                            DOC(ContractStats))
      .def_readonly("iterations", &ContractStats::iterations, DOC(ContractStats, iterations))
      .def_readonly("contractor_calls", &ContractStats::contractor_calls, DOC(ContractStats, contractor_calls))
      .def_readonly("time", &ContractStats::time, DOC(ContractStats, time))
      .def_readonly("empty", &ContractStats::empty, DOC(ContractStats, empty))
      .def_readonly("empty_domain", &ContractStats::empty_domain, DOC(ContractStats, empty_domain))
      .def_readonly("emptiness", &ContractStats::emptiness,
                    DOC(ContractStats, emptiness))
      .def_readonly("empty_contractor", &ContractStats::empty_contractor,
                    DOC(ContractStats, empty_contractor))
      .def_readonly("empty_node", &ContractStats::empty_node,
                    DOC(ContractStats, empty_node))
      .def_readonly("empty_domain_index", &ContractStats::empty_domain_index,
                    DOC(ContractStats, empty_domain_index))
      .def_readonly("empty_domain_name", &ContractStats::empty_domain_name, DOC(ContractStats, empty_domain_name))
      .def_readonly("empty_atom", &ContractStats::empty_atom,
                    DOC(ContractStats, empty_atom))
      .def_readonly("empty_atom_index", &ContractStats::empty_atom_index,
                    DOC(ContractStats, empty_atom_index))
      .def_readonly("empty_time", &ContractStats::empty_time, DOC(ContractStats, empty_time))
      .def_readonly("empty_atom_value", &ContractStats::empty_atom_value, DOC(ContractStats, empty_atom_value))
      .def_readonly("disjoint_atom", &ContractStats::disjoint_atom, DOC(ContractStats, disjoint_atom))
      .def_readonly("disjoint_atom_index", &ContractStats::disjoint_atom_index,
                    DOC(ContractStats, disjoint_atom_index))
      .def_readonly("disjoint_time", &ContractStats::disjoint_time, DOC(ContractStats, disjoint_time))
      .def_readonly("disjoint_value", &ContractStats::disjoint_value, DOC(ContractStats, disjoint_value))
      .def_readonly("summary", &ContractStats::summary, DOC(ContractStats, summary))
      .def("__repr__", [](const ContractStats& s) {
        return "ContractStats(iterations=" + std::to_string(s.iterations) +
               ", contractor_calls=" + std::to_string(s.contractor_calls) + ", time=" + std::to_string(s.time) +
               ", empty=" + (s.empty ? "True, emptiness='" + s.emptiness + "'" : std::string("False")) + ")";
      });

  py::enum_<Scheduling>(m, "Scheduling", DOC(Scheduling))
      .value("Fifo", Scheduling::Fifo)
      .value("Priority", Scheduling::Priority);
  py::class_<ContractorNetwork>(m, "ContractorNetwork",
                                DOC(ContractorNetwork))
      .def("__repr__",
           [](const ContractorNetwork& cn) {
             return "ContractorNetwork(" + std::to_string(cn.nb_ctc()) + " contractors, " + std::to_string(cn.nb_dom()) +
                    " domains)";
           })
      .def(py::init<>(), DOC(ContractorNetwork, ContractorNetwork, void))
      .def("create_dom", py::overload_cast<const Interval&, const std::string&>(&ContractorNetwork::create_dom),
           py::arg("x"), py::arg("name") = "", DOC(ContractorNetwork, create_dom, Interval_string))
      .def("create_dom",
           py::overload_cast<const IntervalVector&, const std::string&>(&ContractorNetwork::create_dom), py::arg("x"),
           py::arg("name") = "", DOC(ContractorNetwork, create_dom, IntervalVector_string))
      .def(
          "set_name",
          [](ContractorNetwork& cn, const py::object& domain, const std::string& name) {
            cn.set_name(to_domain_ref(domain, 0), name);
          },
          py::arg("domain"), py::arg("name"),
          "Names a domain for the reports (stats.emptiness); a TubeVector's components become name[i].")
      .def("domain_name", &ContractorNetwork::domain_name, py::arg("d"), DOC(ContractorNetwork, domain_name))
      .def("set_ctc_name", &ContractorNetwork::set_ctc_name, py::arg("i"), py::arg("name"),
           DOC(ContractorNetwork, set_ctc_name))
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
          "contract", [](ContractorNetwork& cn) { return interruptible(cn, &ContractorNetwork::contract); },
          DOC(ContractorNetwork, contract))
      .def(
          "contract_run", [](ContractorNetwork& cn) { return interruptible(cn, &ContractorNetwork::contract_run); },
          DOC(ContractorNetwork, contract_run))
      .SILLAGE_DEF(ContractorNetwork, update, nogil)
      .def(
          "touched",
          [](ContractorNetwork& cn, const py::object& domain, const Interval& t) {
            cn.touched(to_domain_ref(domain, 0), t);
          },
          py::arg("domain"), py::arg("t") = Interval(), DOC(ContractorNetwork, touched))
      .SILLAGE_DEF(ContractorNetwork, relayout)
      .SILLAGE_DEF(ContractorNetwork, retire, py::arg("nodes"))
      .def("nb_ctc", &ContractorNetwork::nb_ctc, DOC(ContractorNetwork, nb_ctc))
      .def("nb_dom", &ContractorNetwork::nb_dom, DOC(ContractorNetwork, nb_dom))
      .def("ratio", &ContractorNetwork::ratio,
           DOC(ContractorNetwork, ratio))
      .def("budget", &ContractorNetwork::budget,
           DOC(ContractorNetwork, budget))
      .def("stopped_stats", &ContractorNetwork::stopped_stats, DOC(ContractorNetwork, stopped_stats))
      .def("set_budget", &ContractorNetwork::set_budget, py::arg("budget"),
           DOC(ContractorNetwork, set_budget))
      .def("set_ratio", &ContractorNetwork::set_ratio, py::arg("ratio"),
           DOC(ContractorNetwork, set_ratio))
      .def("scheduling", &ContractorNetwork::scheduling, DOC(ContractorNetwork, scheduling))
      .def("set_scheduling", &ContractorNetwork::set_scheduling, py::arg("scheduling"),
           DOC(ContractorNetwork, set_scheduling));
}

}  // namespace sillage::python
