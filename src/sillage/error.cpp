#include "sillage/error.h"

#include <sstream>

namespace sillage {

std::string number_text(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

}  // namespace sillage
