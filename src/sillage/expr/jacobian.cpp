// Function::jacobian: the row-major derivative enclosure as an IntervalMatrix.
#include "sillage/expr/function.h"
#include "sillage/interval/interval_matrix.h"

namespace sillage {

IntervalMatrix Function::jacobian(const IntervalVector& x) const {
  const IntervalVector j = jacobian_vector(x);
  IntervalMatrix m(image_dim(), nb_vars());
  for (std::size_t r = 0; r < image_dim(); ++r)
    for (std::size_t c = 0; c < nb_vars(); ++c) m(r, c) = j[r * nb_vars() + c];
  return m;
}

}  // namespace sillage
