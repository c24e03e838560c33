#pragma once
// TubeDomain: a tube as a network domain. Its atoms follow time: atom 2k is
// gate k ([x](t_k)), atom 2k+1 is slice k ([x](k)), so a tube of N slices has
// 2N+1 atoms and the network tracks (and wakes contractors on) each slice and
// gate on its own.
//
// The identity (key()) is the Tube object, which the domain keeps alive: a
// std::shared_ptr<Tube>, or a component of a TubeVector (a heap object of
// its own, TubeComponentDomain). Refining the TDomain after registration
// changes the layout, and assigning a tube of another TDomain changes the
// times of the slices: check_layout() then throws, as for a resized box.
#include <cstddef>
#include <memory>

#include "sillage/cn/domain.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_atoms.h"

namespace sillage {

class TubeDomain : public Domain, public TubeAtoms {
 public:
  explicit TubeDomain(std::shared_ptr<Tube> x);
  std::size_t nb_atoms() const override { return 2 * nb_slices_ + 1; }
  Interval atom(std::size_t i) const override;
  void set_atom(std::size_t i, const Interval& x) override;
  bool is_empty() const override { return x_->is_empty(); }
  // One pass over the tube: its first empty slice or gate, or gate disjoint
  // from a neighbouring slice (a tube that holds no continuous trajectory).
  EmptyOnInput empty_on_input() const override;
  // The slices holding atoms [first, end) and their gates (a gate with both its slices).
  EmptyOnInput empty_on_input(std::size_t first, std::size_t end) const override;
  const void* key() const override { return x_.get(); }
  std::string kind() const override;
  void check_layout(const std::string& label) const override;
  // Slices added or forgotten (as many forgotten as added is a change too), or another TDomain.
  bool layout_changed() const override {
    return x_->nb_slices() != nb_slices_ || x_->tdomain() != td_ || td_->nb_forgotten() != forgotten_;
  }
  std::string noun() const override { return "tube"; }
  AtomPlace place(std::size_t i) const override;
  std::shared_ptr<Domain> relaid() const override;
  bool appended_only() const override;
  std::optional<std::size_t> dropped_atoms() const override;

  Tube& tube() const { return *x_; }
  const std::shared_ptr<Tube>& object() const { return x_; }
  // The tube is still on the TDomain it had at registration.
  bool same_tdomain() const { return x_->tdomain() == td_; }

 private:
  std::shared_ptr<Tube> x_;
  std::size_t nb_slices_;
  std::shared_ptr<TDomain> td_;  // at registration (kept alive: never a reused address)
  std::size_t forgotten_;        // td_->nb_forgotten() at registration
  double tf_;                    // td_->tf() at registration
};

}  // namespace sillage
