#pragma once
// Ctc: a contractor on boxes (thesis Def. 2.1). contract(x) replaces [x] by a
// sub-box C([x]) that keeps every vector of [x] consistent with the constraint
// (contraction and consistency). contract is const: contractors are
// stateless, so one contractor can serve several threads (parallel SIVIA).
#include <cstddef>
#include <string>

#include "sillage/error.h"
#include "sillage/interval/interval_vector.h"

namespace sillage {

class Ctc {
 public:
  explicit Ctc(std::size_t nb_vars) : nb_vars_(nb_vars) {}
  virtual ~Ctc() = default;
  // Contracts x in place; x.size() must equal nb_vars() (else DimensionError).
  virtual void contract(IntervalVector& x) const = 0;
  // The dimension n of the boxes it contracts.
  std::size_t nb_vars() const { return nb_vars_; }
  // A short human-readable name, used in error messages ("CtcFunction", ...).
  virtual std::string name() const { return "Ctc"; }
  // The name and what tells this contractor from others of its class, for
  // reports such as a network's emptiness explanation ("CtcFunction(x - y)").
  virtual std::string describe() const { return name(); }

 protected:
  // Throws DimensionError naming this contractor when x.size() != nb_vars().
  void check_dim(const IntervalVector& x) const {
    if (x.size() != nb_vars_) {
      throw DimensionError(name() + "::contract: box of size " + std::to_string(x.size()) +
                           ", expected " + std::to_string(nb_vars_));
    }
  }

 private:
  std::size_t nb_vars_;
};

}  // namespace sillage
