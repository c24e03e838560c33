#pragma once
// Angles in the expressions of a problem file. A tube declared `angle =
// true` holds its values modulo 2π, so an expression may read it only where
// a turn more or less changes nothing:
//  - inside sin, cos or tan (v[0] - speed*cos(psi + track)): an ordinary
//    expression, contracted as any other;
//  - as a term of the top-level sum, with sign + or -: the equation is then
//    taken modulo 2π (atan2(y_m - p[1], x_m - p[0]) - psi - bearing_rad +
//    [-0.05, 0.05]), the bearing's wrapping automatic (CtcAngleEquation).
// Anything else (2*psi, psi^2, exp(psi)) is an error naming the angle.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "sillage/ctc/ctc.h"
#include "sillage/problem/var_refs.h"

#include "sillage/problem/problem.h"
#include "sillage/problem/problem_error.h"

namespace sillage::detail {

struct AngleTerms {
  std::vector<std::string> angles;  // the ids of the angle terms, in order
  std::vector<int> signs;           // +1 or -1 each
  std::string rest;                 // the rest of the sum ("0" if none)
};

// `text` uses the identifiers of `angle_ids` for the angle variables. No
// angle term: angles empty and rest == text. ProblemError at pos (what:
// `what`) for an angle read otherwise than above.
AngleTerms angle_terms(const std::string& text, const std::set<std::string>& angle_ids, const SourcePos& pos,
                       const std::string& what);

// Whether some equation of `text` (a tuple "(e1, e2)": each component) has
// angle terms; ProblemError as angle_terms for an angle read otherwise.
bool has_angle_terms(const std::string& text, const std::set<std::string>& angle_ids, const SourcePos& pos,
                     const std::string& what);

// The contractor of the equation r = 0 (r rewritten by rewrite_refs): a
// CtcFunction, or with angle terms a CtcAngleEquation (a tuple with angles:
// each component its own, to a fixed point over the box); `order` receives the
// indices of r.refs in the order of its box (angle terms first).
std::shared_ptr<const Ctc> equation_ctc(const RewrittenExpr& r, const std::set<std::string>& angles, const SourcePos& pos,
                                        const std::string& what, std::vector<std::size_t>& order);

// The names of the angle variables of p.
std::set<std::string> angle_names(const Problem& p);

// Every use of an angle variable in p's constraints is one sillage handles
// modulo 2π (deriv x, eval y with its rate v, expressions as above);
// ProblemError at the constraint otherwise.
void check_angle_uses(const Problem& p);

}  // namespace sillage::detail
