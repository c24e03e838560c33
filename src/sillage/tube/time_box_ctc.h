#pragma once
// A box contractor applied at the time elements of tubes (thesis 3.2.3,
// Def. 3.3): the one implementation behind contract(ctc, tubes)
// (tube_ctc.h) and the network's TubeCtcNode.
//
// Slice k is contracted as the box of the slices k of the tubes, gate k as
// the box of their gates k, each gate first intersected with its two
// neighbouring slices (x(t_k) lies in both). Slices go first, then gates.
// A constant over time p (a variable without a tube) holds at every t: each
// box sees it as narrowed by the previous ones, and it is intersected with
// all of them.
//
// Speed: the boxes go by chunks in column layout; for a CtcFunction they are
// gathered straight into the rows of its HC4 (expr/hc4_rows.h), which walks
// its tape once per chunk; any other contractor is called per box. With
// constants a chunk is one box.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "sillage/ctc/ctc.h"
#include "sillage/tube/tube.h"

namespace sillage::detail {

// Variable v of the contractor: a tube, or (tube null) the constant
// params[param].
struct TimeVar {
  Tube* tube = nullptr;
  std::size_t param = 0;
};

// Told of each time element of a tube that narrowed: (variable, atom,
// before, after); may be empty.
using TimeChange = std::function<void(std::size_t, std::size_t, const Interval&, const Interval&)>;

// "No box was proven empty".
inline constexpr std::size_t kNoTimeAtom = static_cast<std::size_t>(-1);

// Contracts the time elements `atoms` (sorted, tube_atoms.h encoding) of the
// tubes of `vars` (one per variable of ctc, all tubes on one TDomain, at
// least one tube) and the constants `params`. Tubes that changed are
// marked modified (version). A box proven empty stops there: its time elements and the
// constants are set empty and its atom is returned; else kNoTimeAtom.
std::size_t contract_time_elements(const Ctc& ctc, const std::vector<TimeVar>& vars,
                                   std::span<const std::size_t> atoms, IntervalVector& params,
                                   const TimeChange& changed);

}  // namespace sillage::detail
