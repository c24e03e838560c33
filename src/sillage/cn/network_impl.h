#pragma once
// The machinery behind ContractorNetwork (its public header holds only the
// contract): the domains and their names, the nodes and how to rebuild them,
// who watches which atom, and the propagation. ContractorNetwork forwards
// each call here; the methods mean what they mean there.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/cn/dirty_atoms.h"
#include "sillage/cn/watchers.h"

namespace sillage::detail {

class ContractorNetworkImpl {
 public:
  void set_name(const DomainRef& d, const std::string& name);
  const std::string& domain_name(std::size_t d) const { return names_.at(d); }
  void set_ctc_name(std::size_t i, const std::string& name);
  void add(std::shared_ptr<const Ctc> ctc, const std::vector<DomainRef>& domains);
  void add(std::shared_ptr<const NetworkCtc> ctc, const std::vector<DomainRef>& domains);
  void add_node(std::shared_ptr<const CnNode> node);
  std::size_t add_domain(const std::shared_ptr<Domain>& domain);
  ContractStats contract();
  ContractStats contract_run();
  ContractStats update();
  void touched(const DomainRef& d, const Interval& t);
  void relayout();
  void retire(std::vector<std::size_t> nodes);

  std::size_t nb_ctc() const { return nodes_.size(); }
  std::size_t nb_dom() const { return domains_.size(); }
  double ratio() const { return ratio_; }
  void set_ratio(double ratio);
  Scheduling scheduling() const { return scheduling_; }
  void set_scheduling(Scheduling s) { scheduling_ = s; }
  const Budget& budget() const { return budget_; }
  void set_budget(const Budget& budget);
  const ContractStats& stopped_stats() const { return stopped_stats_; }

 private:
  // How to build a node: from its domains as bound (add, add_pending_gates).
  using Make = std::function<std::shared_ptr<const CnNode>(const std::vector<BoundDomain>&)>;

  std::string label(std::size_t d) const;
  // DimensionError naming domain d when its object lost the layout it was registered with.
  void check_layout(std::size_t d) const;
  // "tube 'x'" when named, else label(d).
  std::string noun(std::size_t d) const;
  // Fills the emptiness fields of s: domain d, atom a (kNoAtom: none), found
  // by `by` (a node's describe(); "" for empty on input).
  void explain_empty(ContractStats& s, std::size_t d, std::size_t a, const std::string& by,
                     const Interval& time) const;
  // The fields of s naming domain d, atom a and `by`; the place of a.
  AtomPlace name_empty(ContractStats& s, std::size_t d, std::size_t a, const std::string& by) const;
  // Fills s if domain d holds no value before the propagation (Domain::empty_on_input).
  void explain_empty_on_input(ContractStats& s, std::size_t d) const;
  // The same given what the domain said (Domain::empty_on_input, maybe on some atoms).
  void explain_empty_on_input(ContractStats& s, std::size_t d, const EmptyOnInput& e) const;
  // Domain d's `gate` misses its neighbouring `slice`: both named, with their values and times.
  void explain_disjoint(ContractStats& s, std::size_t d, std::size_t gate, std::size_t slice) const;
  // A contractor (a Python one may) that resized a domain or sampled its
  // TDomain during contract() made the nodes' layouts stale: DimensionError
  // rather than a result computed on the wrong atoms.
  void check_layouts_after(const CnNode& node) const;
  // DimensionError if a domain of the node lost its layout (update() between two relayouts).
  void check_layouts_before(const CnNode& node) const;
  // Same for a node whose run() returned false.
  void explain_node_empty(ContractStats& s, std::size_t i, const NodeRun& run) const;
  // Node i's describe(), with its name (set_ctc_name) if it has one.
  std::string describe_node(std::size_t i) const;
  // The first empty atom of domain d in [first, first + count), or kNoAtom.
  std::size_t first_empty_atom(std::size_t d, std::size_t first, std::size_t count) const;
  // Registers the parts of the references; validates first, so that a failed
  // add leaves the network unchanged.
  std::vector<BoundDomain> bind(const std::vector<DomainRef>& domains);
  // Binds the domains, then adds the node `make` builds on them; if `make`
  // throws, the domains this call registered are forgotten.
  void add_bound(const std::vector<DomainRef>& domains, const Make& make);
  // Samples the pending gates, re-lays out the tube domains and rebuilds the
  // nodes (see "Gates" in contractor_network.h); at the start of contract().
  void add_pending_gates();
  // The propagation: every node first (contract) or only the fresh ones and
  // those woken by touched_ (update).
  ContractStats propagate(bool all);
  // The atoms [first, end) of domain d that a touch at times t names (all of
  // a domain that is no tube, or for t the whole line); false if none.
  bool touched_atoms(std::size_t d, const Interval& t, std::size_t& first, std::size_t& end) const;
  // Fills s if a domain checked before is empty on input where it was touched since (update()).
  void check_touched(ContractStats& s) const;
  // Marks the watchers of the touched atoms dirty and queues them (update()).
  void wake_touched(std::vector<std::size_t>& round, std::vector<char>& queued);
  // Builds every node again from its record on the domains as they are now
  // (relaid out), in the same order; from an empty network when `rebind`
  // (retire: the domains no node uses are dropped).
  void rebuild_nodes(bool rebind);
  // relayout() when every changed domain (changed_, relaid_) only gained
  // atoms at its end and every node on them follows appends: those domains
  // and nodes grown in place, the others untouched (O(nodes on them); the dirty bits laid out
  // again only for the nodes that watch a whole grown domain). False, with nothing
  // changed, when that does not hold (rebuild_nodes then).
  bool grow_in_place();
  // Records the TDomains' layouts as known right (time_layouts_).
  void note_time_layouts();
  // True if no TDomain of the network moved since note_time_layouts().
  bool time_layouts_unchanged() const;
  // Whether every node on domain d can follow its growth (cached in users_[d]).
  bool users_follow(std::size_t d);
  // relayout() or retire() without building any node again: every domain
  // that changed only shifted (Domain::dropped_atoms), every node kept was
  // made by this network and follows the shift (CnNode::follows_appends).
  // The nodes `gone` (empty: none) removed, the domains only they used
  // dropped, the rest renumbered in order; watchers and dirty bits laid out
  // anew (O(nodes + watched atoms)). False, with nothing changed, when that
  // does not hold (rebuild_nodes then).
  bool relay_in_place(const std::vector<char>& gone);
  // Registers node number `id`'s watches, users and dirty bits.
  void watch(std::size_t id, const CnNode& node);
  // The touches (touched()) of domains no longer in the network, dropped.
  void forget_dropped_touches();
  bool acts_on(const CnNode& node, const TDomain& td) const;
  void check_not_contracting(const char* where) const;

  std::vector<std::shared_ptr<Domain>> domains_;
  std::vector<std::string> names_;  // per domain, "" if unnamed
  std::unordered_map<const void*, std::size_t> index_;  // key() -> domain index
  std::vector<Watchers> watchers_;  // per domain
  // Per domain, the nodes with a range on it, ascending, and whether all of
  // them can follow its growth (this network's own, following appends; -1:
  // not known since the last node was added on it).
  struct Users {
    std::vector<std::size_t> nodes;
    int follow = -1;
  };
  std::vector<Users> users_;
  // The TDomains of the tube domains, with their slices and forgotten
  // slices when the layouts were last known right (a full check, or a
  // relayout): while none of them moved, update() checks the layouts of the
  // nodes it runs only, not of every domain.
  struct TimeLayout {
    std::shared_ptr<const TDomain> td;
    std::size_t slices, forgotten;
  };
  std::vector<TimeLayout> time_layouts_;
  // relayout()'s scratch: the domains whose layout changed, and each laid out as it is now.
  std::vector<std::size_t> changed_;
  std::vector<std::shared_ptr<Domain>> relaid_;
  std::vector<std::size_t> grown_from_;  // grow_in_place's scratch: per domain, its former atom count or kNoAtom
  std::vector<char> grown_done_;         // grow_in_place's scratch: per node, grown already
  // Per node, its watched atoms that shrank since it last ran (contract()).
  DirtyAtoms dirty_;
  std::vector<std::shared_ptr<const CnNode>> nodes_;
  // Per node, how to build it again on a new layout (make empty: add_node).
  struct Record {
    std::vector<DomainRef> refs;
    Make make;
  };
  std::vector<Record> records_;
  std::vector<NetworkCtc::Gates> pending_gates_;
  double ratio_ = 0.01;
  Scheduling scheduling_ = Scheduling::Fifo;
  Budget budget_;
  ContractStats stopped_stats_;
  std::vector<std::string> ctc_names_;  // per node, "" if unnamed (set_ctc_name)
  // Per node, added since the last propagation reached it (update() runs it first).
  std::vector<char> fresh_;
  // Per domain, checked for emptiness on input since registered or touched.
  std::vector<char> checked_;
  // Atoms narrowed from outside since the last propagation (touched()).
  struct Touch {
    DomainRef ref;
    Interval t;
  };
  std::vector<Touch> touched_;
  // True during contract(): a contractor calling back into the network (a
  // Python one may) must not grow the arrays contract() is walking.
  bool contracting_ = false;
};

}  // namespace sillage::detail
