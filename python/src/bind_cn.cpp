// ContractorNetwork. Domains are the user's own Interval / IntervalVector /
// Tube / TubeVector objects (shared with C++ through their std::shared_ptr holders), contracted
// in place; DomainRef.component(x, i) / DomainRef.subvector(x, i, j) bind parts
// of a box.
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "bindings.h"
#include "sillage/cn/contractor_network.h"

namespace sillage::python {

std::shared_ptr<const Ctc> hold_ctc(const py::handle& h);  // bind_ctc.cpp

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
      .def("name", &NetworkCtc::name);

  py::class_<DomainRef>(m, "DomainRef", "A part of a box given to ContractorNetwork.add.")
      .def_static("component", py::overload_cast<std::shared_ptr<IntervalVector>, std::size_t>(&DomainRef::component),
                  py::arg("x"), py::arg("i"))
      .def_static("component", py::overload_cast<std::shared_ptr<TubeVector>, std::size_t>(&DomainRef::component),
                  py::arg("x"), py::arg("i"), "Component i of a tube vector, live.")
      .def_static("subvector", &DomainRef::subvector, py::arg("x"), py::arg("i"), py::arg("j"))
      .def("first", &DomainRef::first)
      .def("count", &DomainRef::count);

  py::class_<ContractStats>(m, "ContractStats")
      .def_readonly("iterations", &ContractStats::iterations)
      .def_readonly("contractor_calls", &ContractStats::contractor_calls)
      .def_readonly("time", &ContractStats::time)
      .def_readonly("empty", &ContractStats::empty)
      .def_readonly("empty_domain", &ContractStats::empty_domain)
      .def("__repr__", [](const ContractStats& s) {
        return "ContractStats(iterations=" + std::to_string(s.iterations) +
               ", contractor_calls=" + std::to_string(s.contractor_calls) + ", time=" + std::to_string(s.time) +
               ", empty=" + (s.empty ? "True" : "False") + ")";
      });

  py::class_<ContractorNetwork>(m, "ContractorNetwork")
      .def(py::init<>())
      .def("create_dom", py::overload_cast<const Interval&>(&ContractorNetwork::create_dom), py::arg("x"))
      .def("create_dom", py::overload_cast<const IntervalVector&>(&ContractorNetwork::create_dom), py::arg("x"))
      .def(
          "add",
          [](ContractorNetwork& cn, const py::object& ctc, const py::iterable& domains) {
            std::vector<DomainRef> refs;
            for (const auto& h : domains) refs.push_back(to_domain_ref(h, refs.size()));
            if (py::isinstance<NetworkCtc>(ctc)) {
              cn.add(std::shared_ptr<const NetworkCtc>(ctc.cast<std::shared_ptr<NetworkCtc>>()), refs);
            } else {
              cn.add(hold_ctc(ctc), refs);
            }
          },
          py::arg("ctc"), py::arg("domains"))
      .def("contract", &ContractorNetwork::contract,
           "Propagates to the fixed point; the domains are contracted in place. Returns ContractStats.")
      .def("nb_ctc", &ContractorNetwork::nb_ctc)
      .def("nb_dom", &ContractorNetwork::nb_dom)
      .def("ratio", &ContractorNetwork::ratio)
      .def("set_ratio", &ContractorNetwork::set_ratio, py::arg("ratio"));
}

}  // namespace sillage::python
