#pragma once
// CnNode: a contractor bound to the atoms of the network's domains it acts on.
// The network wakes a node when one of its atoms shrank; run() contracts the
// domains and reports which of its atoms shrank by more than the ratio.
// CtcNode binds a box contractor (Ctc); tube contractors (slice by slice, or
// whole-tube ones such as CtcDeriv) will be other kinds of node.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/domain.h"
#include "sillage/ctc/ctc.h"

namespace sillage {

// Atom `atom` of the network's domain number `domain`.
struct AtomRef {
  std::size_t domain;
  std::size_t atom;
};

class CnNode {
 public:
  explicit CnNode(std::vector<AtomRef> atoms) : atoms_(std::move(atoms)) {}
  virtual ~CnNode() = default;
  virtual std::string name() const = 0;
  const std::vector<AtomRef>& atoms() const { return atoms_; }
  // Contracts the domains; appends to `changed` the positions (in atoms()) of
  // the atoms that shrank by more than `ratio` (see shrink.h). Returns false
  // as soon as a domain became empty.
  virtual bool run(const std::vector<std::shared_ptr<Domain>>& domains, double ratio,
                   std::vector<std::size_t>& changed) const = 0;

 private:
  std::vector<AtomRef> atoms_;
};

// A box contractor on the concatenation of its atoms: read, contract, write
// back intersected (so even a contractor that would enlarge cannot).
class CtcNode : public CnNode {
 public:
  CtcNode(std::shared_ptr<const Ctc> ctc, std::vector<AtomRef> atoms);
  std::string name() const override { return ctc_->name(); }
  bool run(const std::vector<std::shared_ptr<Domain>>& domains, double ratio,
           std::vector<std::size_t>& changed) const override;
  const std::shared_ptr<const Ctc>& ctc() const { return ctc_; }

 private:
  std::shared_ptr<const Ctc> ctc_;
};

}  // namespace sillage
