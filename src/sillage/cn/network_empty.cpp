// The reports of ContractorNetworkImpl: which contractor emptied which domain, and where.
#include "sillage/cn/network_impl.h"

namespace sillage::detail {

std::string ContractorNetworkImpl::noun(std::size_t d) const {
  return names_[d].empty() ? label(d) : domains_[d]->noun() + " '" + names_[d] + "'";
}

std::size_t ContractorNetworkImpl::first_empty_atom(std::size_t d, std::size_t first, std::size_t count) const {
  for (std::size_t a = first; a < first + count; ++a) {
    if (domains_[d]->atom(a).is_empty()) return a;
  }
  return kNoAtom;
}

AtomPlace ContractorNetworkImpl::name_empty(ContractStats& s, std::size_t d, std::size_t a, const std::string& by) const {
  s.empty = true;
  s.empty_domain = label(d);
  s.empty_domain_index = d;
  s.empty_domain_name = names_[d];
  s.empty_contractor = by;
  const AtomPlace place = a == kNoAtom ? AtomPlace{} : domains_[d]->place(a);
  s.empty_atom = place.kind;
  s.empty_atom_index = place.index;
  s.empty_time = place.time;
  return place;
}

void ContractorNetworkImpl::explain_empty(ContractStats& s, std::size_t d, std::size_t a, const std::string& by,
                                      const Interval& time) const {
  const AtomPlace place = name_empty(s, d, a, by);
  const std::string at = place.kind.empty() ? "" : " at " + place.str();
  if (by.empty()) {
    s.emptiness = noun(d) + " was empty on input" + at;
    return;
  }
  s.emptiness = by + " emptied " + noun(d) + at;
  if (!time.is_empty()) {
    s.emptiness += " for t in " + time.str();
    if (place.kind.empty()) s.empty_time = time;
  }
}

namespace {

// "gate 3 [5, 6] at t = 1.5", "slice 2 [0, 1] ([1, 1.5])": an atom with its value, then its time.
std::string with_value(const AtomPlace& p, const Interval& value) {
  const std::string s = p.kind + " " + std::to_string(p.index) + " " + value.str();
  if (p.kind == "gate") return s + " at t = " + number_text(p.time.lb());
  if (p.kind == "slice") return s + " (" + p.time.str() + ")";
  return s;
}

}  // namespace

void ContractorNetworkImpl::explain_disjoint(ContractStats& s, std::size_t d, std::size_t gate, std::size_t slice) const {
  const Domain& dom = *domains_[d];
  const AtomPlace g = name_empty(s, d, gate, ""), x = dom.place(slice);
  s.empty_atom_value = dom.atom(gate);
  s.disjoint_atom = x.kind;
  s.disjoint_atom_index = x.index;
  s.disjoint_time = x.time;
  s.disjoint_value = dom.atom(slice);
  s.emptiness = noun(d) + ": " + with_value(g, s.empty_atom_value) + " does not meet " +
                with_value(x, s.disjoint_value) + ": no continuous trajectory through it (inconsistent input)";
}

// The domains are left as given, as for an empty domain: the report says why.
void ContractorNetworkImpl::explain_empty_on_input(ContractStats& s, std::size_t d) const {
  explain_empty_on_input(s, d, domains_[d]->empty_on_input());
}

void ContractorNetworkImpl::explain_empty_on_input(ContractStats& s, std::size_t d, const EmptyOnInput& e) const {
  if (!e.empty) return;
  if (e.misses == kNoAtom) {
    explain_empty(s, d, e.atom, "", Interval::empty());
  } else {
    explain_disjoint(s, d, e.atom, e.misses);
  }
}

std::string ContractorNetworkImpl::describe_node(std::size_t i) const {
  const std::string d = nodes_[i]->describe();
  return i < ctc_names_.size() && !ctc_names_[i].empty() ? d + " (" + ctc_names_[i] + ")" : d;
}

void ContractorNetworkImpl::explain_node_empty(ContractStats& s, std::size_t i, const NodeRun& run) const {
  const CnNode& node = *nodes_[i];
  if (node.ranges().empty()) {
    s.empty = true;
    s.empty_contractor = describe_node(i);
    s.emptiness = s.empty_contractor + " found no solution";
    return;
  }
  // The atom the node names, else its first empty atom, else its first domain.
  std::size_t g = 0, a = kNoAtom;
  if (run.empty_at < node.nb_atoms()) {
    g = node.range_of(run.empty_at);
    a = node.ranges()[g].first + run.empty_at - node.offset(g);
  } else {
    for (g = 0; g < node.ranges().size(); ++g) {
      const AtomRange& r = node.ranges()[g];
      if ((a = first_empty_atom(r.domain, r.first, r.count)) != kNoAtom) break;
    }
    if (g == node.ranges().size()) g = 0;
  }
  explain_empty(s, node.ranges()[g].domain, a, describe_node(i), run.empty_time);
}

}  // namespace sillage::detail
