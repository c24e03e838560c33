#pragma once
// What CtcHeading and CtcHeadingWindow share: the direction of a
// displacement box that excludes 0, the meet of an unwrapped angle with a
// direction known modulo 2π, and the end of a contraction of p and ψ.
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "sillage/cn/cn_node.h"
#include "sillage/cn/tube_node.h"
#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"

namespace sillage::detail {

// The directions of the box (dx, dy), which does not hold 0: the narrower of
// atan2 (cut on the negative x axis) and atan2 of the opposite box plus π
// (cut on the positive x axis). Narrower than π.
Interval box_direction(const Interval& dx, const Interval& dy);

// s ∩ (r + 2πZ), hulled; s unchanged when s or r is unbounded or s is too
// wide to enumerate its turns (> 1e6).
Interval periodic_meet(const Interval& s, const Interval& r);

// Where a contraction found no trajectory: the tube (0: px, 1: py, 2: psi) and its atom.
struct HeadingEmptyAt {
  std::size_t tube = 0, atom = kNoAtom;
};

// x ∩= y; false when empty.
inline bool narrow(Interval& x, const Interval& y) {
  x &= y;
  return !x.is_empty();
}

// A tube written by a heading contraction: its slices and gates in place;
// its version steps when this ends (after finish_heading).
struct HeadingTube {
  explicit HeadingTube(Tube& x) : w(x.write()), slices(w.slices()), gates(w.gates()) {}
  Tube::Writer w;
  std::span<Interval> slices, gates;
};

// The end of a contraction of (px, py, psi): all three set empty when !ok
// (their HeadingTube writers mark them modified). Returns ok.
bool finish_heading(bool ok, Tube& px, Tube& py, Tube& psi);

// The network node of a heading contractor on whole tubes {px, py, psi, ...}
// (`count` of them, on one TDomain): run_heading() runs a contraction of
// the first three and reports to the network what shrank and where it
// found emptiness.
class HeadingNodeBase : public TubeNode {
 public:
  // Nothing in it depends on the number of slices (a window node's cache
  // follows them): grown in place when its tubes gain slices (online estimation).
  bool follows_appends() const override { return true; }

 protected:
  HeadingNodeBase(const std::string& name, const std::vector<BoundDomain>& args, std::size_t count, const char* what);
  Tube& tube_arg(std::size_t i) const { return tube(i)->tube(); }
  bool run_heading(NodeRun& r, const std::function<bool(HeadingEmptyAt&)>& contract) const;
};

}  // namespace sillage::detail
