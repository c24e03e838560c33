#pragma once
// What a figure shows of a loop detection Ω_i (thesis Figs. 6.12-6.13): a
// complete detection proven by the degree test (orange), a complete one the
// test cannot conclude on (black), and a partial one, touching the sides or
// the diagonal of the t-plane, on which no proof is attempted (grey).
#include <string>

#include "sillage/figures/style.h"
#include "sillage/loops/tplane.h"

namespace sillage {

// What a figure shows of a detection: proven (orange), unproven (black), partial (grey).
enum class LoopStatus { Proven, Unproven, Partial };

// The status of a detection: Proven (by the degree test T), Unproven (complete, not proven) or
// Partial (not complete).
LoopStatus loop_status(const Loop& loop);
std::string to_string(LoopStatus status);  // "proven", "unproven", "partial"

// Fill and stroke colours of the status; css_class is to_string(status).
// Fill opacity 0.45 so that what lies below (leaves, trajectory) shows.
Style loop_style(LoopStatus status);

}  // namespace sillage
