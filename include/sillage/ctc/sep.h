#pragma once
// Sep: a separator, a pair of complementary contractors. separate(x_in, x_out)
// contracts x_in so that the removed part lies inside the set X (inner
// contractor: what it removes is proven in X) and x_out so that the removed
// part lies outside X (outer contractor: what it removes is proven out of X).
// Both start as copies of the same box. Used by SIVIA for inner approximations.
#include <cstddef>
#include <string>

#include "sillage/error.h"
#include "sillage/interval/interval_vector.h"

namespace sillage {

class Sep {
 public:
  explicit Sep(std::size_t nb_vars) : nb_vars_(nb_vars) {}
  virtual ~Sep() = default;
  // Contracts x_in (inner) and x_out (outer) in place (Python: returns both).
  virtual void separate(IntervalVector& x_in, IntervalVector& x_out) const = 0;
  // The dimension n of the boxes it separates.
  std::size_t nb_vars() const { return nb_vars_; }
  // A short human-readable name, used in error messages ("SepFunction", ...).
  virtual std::string name() const { return "Sep"; }

 protected:
  // Throws DimensionError naming this separator unless both boxes have nb_vars() components.
  void check_dim(const IntervalVector& x_in, const IntervalVector& x_out) const {
    if (x_in.size() != nb_vars_ || x_out.size() != nb_vars_) {
      throw DimensionError(name() + "::separate: boxes of sizes " + std::to_string(x_in.size()) + " and " +
                           std::to_string(x_out.size()) + ", expected " + std::to_string(nb_vars_));
    }
  }

 private:
  std::size_t nb_vars_;
};

}  // namespace sillage
