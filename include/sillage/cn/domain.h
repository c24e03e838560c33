#pragma once
// Domain: a variable of a contractor network, seen as a flat array of scalar
// "atoms" (intervals) that contractors read and contract. An Interval is one
// atom, a box of size n is n atoms; a tube will be its slices (and gates), so
// that a pointwise constraint can be bound slice by slice and the network can
// track changes, and wake contractors, atom by atom.
//
// A domain wraps a user object held by std::shared_ptr: its identity (key()) is
// that heap object, which the network keeps alive, so it never moves, whatever
// happens to the containers of the user's shared_ptrs.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "sillage/interval/interval_vector.h"

namespace sillage {

// Where an atom lies in its domain, for reports: a component of a box, a
// slice or gate of a tube (with its time); kind "" for a one-atom domain.
struct AtomPlace {
  std::string kind;  // "component", "slice", "gate" or ""
  std::size_t index = 0;
  Interval time = Interval::empty();  // tubes: the slice's time interval, the gate's time
  // "slice 4 [0.4, 0.5]", "gate 2 (t = 0.2)", "component 1" or "".
  std::string str() const;
};

// "No atom" (NodeRun::empty_at, EmptyOnInput).
inline constexpr std::size_t kNoAtom = static_cast<std::size_t>(-1);

// Why a domain holds no value before any contraction: an empty atom, or an
// atom that misses another one (a tube's gate disjoint from a neighbouring
// slice: no continuous trajectory goes through it).
struct EmptyOnInput {
  bool empty = false;            // the domain holds no value
  std::size_t atom = kNoAtom;    // the empty atom (kNoAtom: none named), or the gate that misses `misses`
  std::size_t misses = kNoAtom;  // the slice the gate does not meet; kNoAtom if `atom` is empty
};

class Domain {
 public:
  virtual ~Domain() = default;
  virtual std::size_t nb_atoms() const = 0;
  virtual Interval atom(std::size_t i) const = 0;
  // Replaces atom i (the network only ever narrows it).
  virtual void set_atom(std::size_t i, const Interval& x) = 0;
  virtual bool is_empty() const = 0;
  // Checked by contract() before the propagation: why the domain holds no
  // value (by default its first empty atom; a tube also finds a gate
  // disjoint from a neighbouring slice, the first flaw in time order).
  virtual EmptyOnInput empty_on_input() const;
  // The same for atoms [first, end) only, when the others are known to hold
  // values (checked before, not changed since): a tube checks its slices
  // and gates there. The whole domain by default.
  virtual EmptyOnInput empty_on_input(std::size_t first, std::size_t end) const {
    (void)first, (void)end;
    return empty_on_input();
  }
  // The wrapped object: two domains with the same key are the same variable.
  virtual const void* key() const = 0;
  // "Interval", "IntervalVector(3)", ...
  virtual std::string kind() const = 0;
  // Throws DimensionError (naming `label`) when the object no longer has the
  // layout it had when registered (a box resized behind the network's back).
  virtual void check_layout(const std::string& label) const { (void)label; }
  // True when check_layout would throw (cheap: checked after every node run).
  virtual bool layout_changed() const { return false; }
  // A fresh domain on the same object with its current layout, when the
  // layout changed only because its TDomain gained time points; nullptr
  // otherwise (the network then reports the change as an error).
  virtual std::shared_ptr<Domain> relaid() const { return nullptr; }
  // True when the layout changed only by atoms appended at the end (a
  // tube's TDomain that grew): the atoms it had keep their indices.
  virtual bool appended_only() const { return false; }
  // When the layout changed only by atoms dropped at the start and appended
  // at the end (a tube's TDomain that forgot its past and grew): how many
  // were dropped (the atom a it had is now a - dropped). None otherwise.
  virtual std::optional<std::size_t> dropped_atoms() const { return std::nullopt; }
  // The word for this kind of domain in reports: "interval", "box", "tube".
  virtual std::string noun() const { return "domain"; }
  // Where atom i lies (kind "" by default).
  virtual AtomPlace place(std::size_t i) const {
    (void)i;
    return {};
  }
};

class IntervalDomain : public Domain {
 public:
  explicit IntervalDomain(std::shared_ptr<Interval> x);
  std::size_t nb_atoms() const override { return 1; }
  Interval atom(std::size_t) const override { return *x_; }
  void set_atom(std::size_t, const Interval& x) override { *x_ = x; }
  bool is_empty() const override { return x_->is_empty(); }
  const void* key() const override { return x_.get(); }
  std::string kind() const override { return "Interval"; }
  std::string noun() const override { return "interval"; }
  const std::shared_ptr<Interval>& object() const { return x_; }

 private:
  std::shared_ptr<Interval> x_;
};

class BoxDomain : public Domain {
 public:
  explicit BoxDomain(std::shared_ptr<IntervalVector> x);
  std::size_t nb_atoms() const override { return size_; }
  Interval atom(std::size_t i) const override { return (*x_)[i]; }
  // An empty component empties the whole box (the IntervalVector convention).
  void set_atom(std::size_t i, const Interval& x) override;
  bool is_empty() const override { return x_->is_empty(); }
  const void* key() const override { return x_.get(); }
  std::string kind() const override;
  void check_layout(const std::string& label) const override;
  bool layout_changed() const override { return x_->size() != size_; }
  std::string noun() const override { return "box"; }
  AtomPlace place(std::size_t i) const override;
  const std::shared_ptr<IntervalVector>& object() const { return x_; }

 private:
  std::shared_ptr<IntervalVector> x_;
  std::size_t size_;
};

}  // namespace sillage
