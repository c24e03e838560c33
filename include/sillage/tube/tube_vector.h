#pragma once
// TubeVector: n scalar tubes on one TDomain, an enclosure of vector
// trajectories x : [t_0, t_N] -> IR^n (thesis 3.2.2). Component i is a Tube,
// returned by reference (operator[]) so that it can be read and contracted in
// place. Value semantics like Tube. Each component is a heap object of its
// own (TubeComponents): references to it stay valid when a new value is
// assigned to the vector, which is what a ContractorNetwork relies on.
#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "sillage/interval/interval_vector.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube_components.h"
#include "sillage/tube/tube.h"

namespace sillage {

class TubeVector {
 public:
  // n components, each slice and gate = x. Error if n == 0.
  TubeVector(std::shared_ptr<TDomain> td, std::size_t n, const Interval& x = Interval());
  // Component i = the box's component i (constant in time).
  TubeVector(std::shared_ptr<TDomain> td, const IntervalVector& x);
  // From a vector expression of t, "(e1, e2, ...)" (or a scalar one): one
  // batch evaluation for all components.
  TubeVector(std::shared_ptr<TDomain> td, const std::string& expr_of_t);
  TubeVector(std::shared_ptr<TDomain> td, const Function& f);  // f of one variable t
  // From tubes (at least one, all on the same TDomain; DimensionError otherwise).
  explicit TubeVector(std::vector<Tube> components);

  // The dimension n.
  std::size_t size() const { return x_.size(); }
  // The TDomain (shared).
  const std::shared_ptr<TDomain>& tdomain() const { return x_.front().tdomain(); }
  // N, the number of slices.
  std::size_t nb_slices() const { return x_.front().nb_slices(); }

  // Component i, a live reference (OutOfRangeError if i >= size()).
  Tube& operator[](std::size_t i);
  const Tube& operator[](std::size_t i) const;
  // Component i shared: the same object as (*this)[i], alive as long as
  // someone holds it (OutOfRangeError if i >= size()).
  std::shared_ptr<Tube> shared_component(std::size_t i);
  // Components i..j (inclusive, like IntervalVector::subvector), copied.
  TubeVector subvector(std::size_t i, std::size_t j) const;

  // The box of slice k.
  IntervalVector slice(std::size_t k) const;
  // The box of gate k.
  IntervalVector gate(std::size_t k) const;
  IntervalVector operator()(double t) const;          // component-wise Tube::operator()(t)
  IntervalVector operator()(const Interval& t) const;  // component-wise [x]([t])
  // The box hull of every slice and gate.
  IntervalVector codomain() const;

  // Sum over slices of width(t slice) * volume of the slice box, rounded up.
  double volume() const;
  double max_thickness() const;  // max over components
  bool is_empty() const;         // some component is empty
  // Component-wise Tube.is_subset.
  bool is_subset(const TubeVector& y) const;
  // One trajectory per component (DimensionError if the counts differ).
  bool contains(const std::vector<Trajectory>& x) const;
  bool operator==(const TubeVector& y) const;
  bool operator!=(const TubeVector& y) const { return !(*this == y); }
  TubeVector& operator&=(const TubeVector& y);
  TubeVector& operator|=(const TubeVector& y);

  void set(const IntervalVector& y);                  // every slice and gate
  void set(const IntervalVector& y, std::size_t k);   // slice k (see Tube::set)
  // Gate k := the box y.
  void set_gate(std::size_t k, const IntervalVector& y);

 private:
  void check_size(std::size_t n, const char* where) const;
  TubeComponents x_;
};

std::ostream& operator<<(std::ostream& os, const TubeVector& x);

}  // namespace sillage
