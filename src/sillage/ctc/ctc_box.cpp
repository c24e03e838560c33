#include "sillage/ctc/ctc_box.h"

namespace sillage {

void CtcBox::contract(IntervalVector& x) const {
  check_dim(x);
  x &= box_;
}

}  // namespace sillage
