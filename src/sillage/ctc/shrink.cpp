#include "sillage/ctc/shrink.h"

#include <cmath>
#include <string>

#include "sillage/error.h"

namespace sillage {

bool shrank(const IntervalVector& before, const IntervalVector& after, double ratio) {
  check_same_size(before.size(), after.size(), "shrank");
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (shrank(before[i], after[i], ratio)) return true;
  }
  return false;
}

void check_ratio(double ratio, const char* where) {
  if (!(ratio >= 0.0 && ratio < 1.0)) {
    throw Error(std::string(where) + ": ratio must lie in [0, 1), got " + number_text(ratio));
  }
}

}  // namespace sillage
