#pragma once
// ContractorNetwork (thesis 2.3.1): variables (domains) linked by contractors,
// propagated to a fixed point.
//
//   ContractorNetwork cn;
//   auto x = cn.create_dom(IntervalVector(2));
//   auto rho = cn.create_dom(Interval(3.63, 4.43));
//   cn.add(ctc, {x, rho});            // ctc acts on (x1, x2, rho)
//   ContractStats s = cn.contract();  // x and rho are contracted in place
//
// Domains are the user's own objects, shared: std::shared_ptr<Interval>,
// std::shared_ptr<IntervalVector>, std::shared_ptr<Tube>,
// std::shared_ptr<TubeVector>, or a part of a box or tube vector
// (DomainRef::component / subvector). Their identity is the shared heap
// object, so moving or copying the containers of the shared_ptrs changes
// nothing. The domains of one add() are concatenated into the box given to
// the contractor; their sizes must add up to its nb_vars() (DimensionError
// naming it otherwise).
//
// Tubes. When an argument of add(ctc, ...) is a tube (or tube vector), ctc is
// applied at every time (TubeCtcNode): a tube counts as one variable, the
// other arguments are constants over time. Contractors on whole tubes
// (CtcDeriv, CtcEval) come as NetworkCtc. The network tracks each slice and
// gate of a tube as an atom of its own: a contraction of slice k wakes only
// the contractors acting on slice k, and tells them which slices changed.
//
// Propagation: a queue of contractors, processed in rounds. Round 1 runs every
// contractor once, in the order of add(); each atom (scalar component) that a
// contractor shrank by more than ratio() (shrink.h; default 0.01) wakes the
// other contractors acting on it, which run in the next round (each contractor
// at most once per round; one already waiting in the current round is not
// queued again; a node may ask to run in the next round, NodeRun::again;
// set_scheduling: the order within a round, as woken or by expected
// contraction). The propagation stops when a round wakes nobody, or at once
// when a domain becomes empty (that domain is set empty, the others keep their
// last values, which remain valid enclosures; ContractStats::empty tells).
//
// Gates. A NetworkCtc may ask for time points (NetworkCtc::gates_for; CtcEval
// with gates_at_time_bounds: the bounds of [t]). They are added to the TDomain
// at the next contract(), before the propagation; the tube domains on it are
// then re-laid out and every node is rebuilt from its add() on the new
// slices. Not done (the tubes keep their slices) when a node given by
// add_node acts on a tube of that TDomain: it could not be rebuilt.
//
// Emptiness is an answer (no trajectory, no solution fits the data and the
// bounds), never a success: ContractStats says which contractor emptied which
// domain, and where (the slice or gate of a tube, and its time), in words
// (emptiness) and field by field. Before the propagation contract() checks
// each domain once: an empty one, or a tube with a gate disjoint from a
// neighbouring slice (no continuous trajectory through it), is no solution,
// reported with both atoms and left as given. Name the domains (set_name,
// create_dom) to read "tube 'x'" rather than "domain 3 (Tube(100 slices))".
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/cn/cn_node.h"
#include "sillage/cn/domain_ref.h"
#include "sillage/cn/network_ctc.h"
#include "sillage/cn/scheduling.h"

namespace sillage {

namespace detail {
class ContractorNetworkImpl;
}

// What contract() did. An empty network is an answer (no solution), explained by
// emptiness and the empty_* fields.
struct ContractStats {
  // Rounds of the queue (see above). The thesis counts sweeps over all the
  // contractors up to a sweep that changes nothing; rounds run only the woken
  // contractors, and no idle round is counted.
  std::size_t iterations = 0;
  std::size_t contractor_calls = 0;  // calls of Ctc::contract (node runs)
  double time = 0.0;                 // wall-clock seconds of this contract()
  bool empty = false;                // a domain became (or was) empty: no solution
  std::string empty_domain;          // which one, e.g. "domain 2 (Interval)"
  // Why, e.g. "CtcEval emptied tube 'x' at slice 412 [41.2, 41.3] for t in
  // [41.22, 41.28]", "CtcFunction(x - y) emptied interval 'y'", "box 'p' was
  // empty on input at component 1"; "" when not empty.
  std::string emptiness;
  std::string empty_contractor;          // describe() of the contractor; "" if empty on input
  std::size_t empty_node = static_cast<std::size_t>(-1);  // its index in add() order; -1 if empty on input
  std::size_t empty_domain_index = 0;    // the emptied domain's index in the network
  std::string empty_domain_name;         // its name, "" if it has none
  std::string empty_atom;                // "slice", "gate", "component" or "" (the whole domain)
  std::size_t empty_atom_index = 0;      // index of the slice, gate or component that became empty
  Interval empty_time = Interval::empty();  // time of the slice or gate; CtcEval: also its [t]
  // Inconsistent input (a tube's gate, empty_atom, disjoint from a
  // neighbouring slice: no continuous trajectory through it): the gate's
  // value; empty otherwise.
  Interval empty_atom_value = Interval::empty();
  std::string disjoint_atom;                    // the slice that gate misses: "slice", or "" (not that case)
  std::size_t disjoint_atom_index = 0;          // its index
  Interval disjoint_time = Interval::empty();   // its time interval
  Interval disjoint_value = Interval::empty();  // its value
  // How the propagation ended (outcome.h): Converged at the fixed point, NoSolution (reason: the
  // emptiness above), or, from contract_run(), Stopped (a budget spent: which one) or Cancelled;
  // its counters are the rounds, the contractor calls and the time above.
  Summary summary;
};

class ContractorNetwork {
 public:
  // An empty network.
  ContractorNetwork();
  ~ContractorNetwork();
  ContractorNetwork(const ContractorNetwork&) = delete;
  ContractorNetwork& operator=(const ContractorNetwork&) = delete;

  // New shared domains owned together by the caller and the network,
  // optionally named (see set_name).
  std::shared_ptr<Interval> create_dom(const Interval& x, const std::string& name = "");
  // A new box domain (a copy of x), optionally named.
  std::shared_ptr<IntervalVector> create_dom(const IntervalVector& x, const std::string& name = "");
  // Names the domain(s) of d for the reports (registering them if new): a
  // tube vector's components become name[0], name[1], ... Error if empty.
  void set_name(const DomainRef& d, const std::string& name);
  // The name of domain number d ("" if none).
  const std::string& domain_name(std::size_t d) const;

  // Names contractor i (in add order: nb_ctc() - 1 is the last added) for the
  // reports, e.g. the measurement it stands for: "CtcEval (ranges line 12)
  // emptied tube 'x' ...". Error if there is no contractor i or name is empty.
  void set_ctc_name(std::size_t i, const std::string& name);

  // Binds ctc to the concatenation of the domains (registered on first use);
  // applied at every time if a domain is a tube (see above).
  void add(std::shared_ptr<const Ctc> ctc, const std::vector<DomainRef>& domains);
  // A contractor with a node of its own (CtcDeriv, CtcEval, ...).
  void add(std::shared_ptr<const NetworkCtc> ctc, const std::vector<DomainRef>& domains);
  // Any kind of node (extension point for tube contractors).
  void add_node(std::shared_ptr<const CnNode> node);
  // Registers a domain (idempotent); returns its index in the network.
  std::size_t add_domain(const std::shared_ptr<Domain>& domain);

  // Propagates to the fixed point (see the top of this header); the domains are contracted in
  // place. stats.empty means no solution, and stats.emptiness says which contractor emptied
  // which domain. budget() limits it (BudgetExceeded, Cancelled; Python: Ctrl-C raises
  // KeyboardInterrupt). Budget::progress, if set, is called once per round.
  ContractStats contract();
  // The same, but a spent budget or a cancellation (of budget()'s token) is an answer rather
  // than an exception: the stats so far with summary.status Stopped or Cancelled and its reason;
  // the domains are contracted as far as the propagation got, still enclosures of every solution.
  ContractStats contract_run();

  // Online use (docs/online.md): a network that changes between contractions.
  //
  // Contracts from what changed since the last contract() or update(): the
  // contractors added since then run first (on their whole arguments), then
  // the ones woken by the atoms marked with touched() and by what the runs
  // shrink. A network at its fixed point that gained one measurement
  // contracts only what that measurement reaches. Answers as contract_run()
  // (a spent budget or a cancellation is a status, not an exception).
  ContractStats update();
  // Marks the atoms of d as narrowed from outside the network (new inputs
  // written into a tube, a box set by hand), so that update() wakes the
  // contractors acting on them: for a tube, its slices and gates meeting t
  // (every atom when t is the whole line); for an Interval or box, all its
  // components. Error if t is empty or d is not in the network.
  void touched(const DomainRef& d, const Interval& t = Interval());
  // After a TDomain of the network's tubes grew (TDomain::extend), forgot
  // its past (forget_before) or gained time points: re-lays out those tubes
  // and the contractors on them. Those that follow appends
  // (CnNode::follows_appends) follow a domain that grew or forgot in place;
  // otherwise (time points sampled inside, or a contractor that does not
  // follow) every contractor is rebuilt on the new slices from its add(). A
  // contractor given by add_node cannot be rebuilt: Error if one acts on a
  // changed tube then. Nothing is contracted.
  void relayout();
  // Removes the contractors numbered `nodes` (add() order; the ones after
  // move down, and their names with them), then forgets the domains no
  // remaining contractor uses (their objects keep their values) and lays
  // the rest out anew, as relayout() (in place when it can: an online
  // estimator retires its old observations as its window moves). Error if
  // an index is out of range or, when the contractors must be rebuilt, a
  // remaining one was given by add_node.
  void retire(std::vector<std::size_t> nodes);

  // Number of contractors added.
  std::size_t nb_ctc() const;
  // Number of domains known to the network.
  std::size_t nb_dom() const;
  // The shrink ratio above which a contracted atom wakes its other contractors (default 0.01).
  double ratio() const;
  // Sets ratio(): a component that shrank by more than ratio wakes the contractors acting on
  // it; 0 <= ratio < 1 (else Error).
  void set_ratio(double ratio);
  // The order of the contractors within a round (scheduling.h; default Fifo).
  Scheduling scheduling() const;
  // Sets scheduling(): Fifo or Priority (by expected contraction over cost).
  void set_scheduling(Scheduling s);
  // Limits of contract(): max_boxes counts contractor calls (10^7 by
  // default), max_seconds the wall-clock time, cancel stops it from another
  // thread (Python: Ctrl-C), between contractor calls and within the long
  // ones (CtcIvp, CtcPImpliesZ). Exceeded: BudgetExceeded (cancelled: Cancelled),
  // the domains left contracted as far as they got (still enclosures).
  const Budget& budget() const;
  // Sets budget(); contract() then raises BudgetExceeded past it (the domains stay enclosures).
  void set_budget(const Budget& budget);
  // What the last contract() that raised BudgetExceeded did before it stopped
  // (its rounds and contractor runs, the time).
  const ContractStats& stopped_stats() const;

 private:
  // The machinery (src/sillage/cn/network_impl.h): domains, nodes, watchers,
  // the propagation. Kept out of this header, which holds the contract.
  std::unique_ptr<detail::ContractorNetworkImpl> impl_;
};

}  // namespace sillage
