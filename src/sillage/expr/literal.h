#pragma once
// Number literals: rigorous enclosures of decimal texts and the reverse,
// the shortest text whose enclosure is a given constant.
#include <string>
#include <string_view>

#include "sillage/interval/interval.h"

namespace sillage::detail {

// Enclosure of the real number written `text` (digits, optional '.', optional
// exponent, no sign; e.g. "0.1", "2e-3", ".5"): the degenerate interval when
// the number is a double, else the two doubles around it. Throws ParseError
// if `text` is not such a literal.
Interval decimal_enclosure(std::string_view text);

// A literal t with decimal_enclosure(t) == c (a leading '-' for negative
// values, "[lb, ub]" when no plain number fits; bounds "inf", "[empty]").
std::string literal_str(const Interval& c);

}  // namespace sillage::detail
