#pragma once
// An interval in 6 significant digits for people (reports, explanations),
// rounded outward so that the text still encloses the set (internal).
#include <string>

#include "sillage/interval/interval.h"

namespace sillage::detail {

// "[0.639999, 1.81001]", "∅" for the empty set, "[-inf, 3]" for an unbounded one.
std::string interval_text(const Interval& x);

}  // namespace sillage::detail
