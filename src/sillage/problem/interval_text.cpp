#include "sillage/problem/interval_text.h"

#include <cfenv>
#include <cstdio>

namespace sillage::detail {

namespace {

// x in 6 digits rounded toward `mode` (glibc's printf follows the rounding
// mode): a lower bound printed down, an upper one up.
std::string directed(double x, int mode) {
  const int saved = std::fegetround();
  std::fesetround(mode);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  std::fesetround(saved);
  return buf;
}

}  // namespace

std::string interval_text(const Interval& x) {
  if (x.is_empty()) return "∅";
  std::string s = "[";  // appended: "[" + a temporary is a false -Wrestrict of GCC 12
  s += directed(x.lb(), FE_DOWNWARD);
  s += ", ";
  s += directed(x.ub(), FE_UPWARD);
  s += ']';
  return s;
}

}  // namespace sillage::detail
