#pragma once
// The figures of a failing solve (internal, report_html): a tube as it was
// just before the contradiction (SolveResult::before_empty), with the
// statements that the explanation blames marked on it: a gate's stated value
// (red) and the value the relaxed problem proves there (green), a bound's
// stated band, the time span of a run of rows (orange).
#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/problem/explain_empty.h"
#include "sillage/tube/tube.h"

namespace sillage::detail {

// A box of (time, value) drawn over a tube, with its style (its label goes to the legend).
struct FigureMark {
  IntervalVector box;
  Style style;
};

// The marks of the explanation's relaxations on component i of the tube variable `var`
// (a run of rows: on the tubes its eval evaluates).
std::vector<FigureMark> blamed_marks(const Problem& p, const Explanation& e, const std::string& var, std::size_t i);

// The tube over time with the marks on top, the window grown to hold the finite ones.
Figure marked_tube_figure(const Tube& x, const std::string& name, const std::string& title,
                          const std::vector<FigureMark>& marks);

}  // namespace sillage::detail
