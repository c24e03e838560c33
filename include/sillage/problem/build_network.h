#pragma once
// Builds the domains and the ContractorNetwork of a Problem for one slice
// width δ: one TDomain (sampled at the times of the 'at' bounds that are
// doubles; a value at a decimal such as 0.1, or at a table's stamp, is a fix of
// a CtcEvalList at the time as written, an interval between two doubles), a Tube or
// TubeVector per tube variable, an Interval or IntervalVector per constant
// one; per constraint: a CtcFunction (applied at every time when it involves
// tubes), a CtcDeriv, a CtcIncrement, or per data row a CtcEval and the
// CtcFunction of its observation. Constraints are added in file order, so the
// propagation is the one of a hand-written network adding them in that order.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/problem/problem.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// The domain of one variable: exactly one pointer is set, by kind.
struct VarDomain {
  std::shared_ptr<const VarSpec> spec;  // a copy: the domains outlive the Problem
  std::shared_ptr<TubeVector> tubes;       // tube (size 1) and tube_vector
  std::shared_ptr<Interval> interval;      // interval
  std::shared_ptr<IntervalVector> box;     // box
  DomainRef component(std::size_t i) const;
  // A tube variable as one domain: the Tube of a scalar tube, else the TubeVector.
  DomainRef whole() const;
  std::size_t memory_bytes() const;
};

struct BuiltProblem {
  std::shared_ptr<TDomain> td;
  std::vector<VarDomain> vars;  // in the order of Problem::vars
  std::unique_ptr<ContractorNetwork> cn;
  std::vector<std::size_t> first_node;  // per constraint (file order): its first node in the network
  std::vector<std::size_t> order;       // the constraints in the order they entered the network
  std::size_t extra_domains = 0;        // per-row times, values and columns of the evals
  // After the constraints' nodes, from first_value_node: one per variable with
  // values stated at times between two doubles ('at' decimals, a table's
  // stamps), what it holds, for messages.
  std::size_t first_value_node = 0;
  std::vector<std::string> value_nodes;
  const VarDomain& var(const std::string& name) const;
  // The constraint that added node n.
  std::size_t constraint_of_node(std::size_t n) const;
  std::size_t memory_bytes() const;  // the tubes and boxes
};

// The order the constraints of p enter the network (indices into p.constraints).
std::vector<std::size_t> constraint_order(const Problem& p);

// δ > 0. Error (ProblemError) for a bound or a row that cannot be built.
BuiltProblem build_network(const Problem& p, double delta);

// The same on the time points given (strictly increasing, from t0 to tf; the
// gates of the file are added to them): slices of several widths, as the
// automatic δ refines the time regions where the tubes are thick.
BuiltProblem build_network(const Problem& p, const std::vector<double>& points);

// The slice count δ gives on the problem's time domain.
std::size_t nb_slices_for(const Problem& p, double delta);

// The memory a solve of p on `slices` slices takes at its peak, estimated:
// 150 bytes per slice of each tube component (its slice and gate, its
// synthesis tree, the network's change tracking, the outputs written from it:
// 142 measured on dead_reckoning.toml from 64 000 to 320 000 slices), 200 per
// eval row, 8 MiB for the program. An estimate for planning, not a bound:
// within a factor 2 of the peak measured on the example problems.
std::size_t peak_memory_estimate(const Problem& p, std::size_t slices);

// Error, before anything is built, when peak_memory_estimate(p, slices) is
// above the machine's physical memory: the estimate, the memory and `what`
// gave that many slices ("--delta 1e-6"), instead of a bare out-of-memory later.
void check_memory(const Problem& p, std::size_t slices, const std::string& what);

}  // namespace sillage
