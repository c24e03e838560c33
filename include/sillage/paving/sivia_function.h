#pragma once
// SIVIA over expression Functions: the natural inclusion function [f] of a
// Function, with an exact notion of X = { x : f(x) is defined and f(x) ∈ Y }.
// Set-based evaluation ignores the points where f is undefined (sqrt of a
// negative number, ...), so a box is tagged Inner only when, in addition to
// [f]([x]) ⊂ Y, f is proven defined on the whole box (DefinitionCheck).
#include "sillage/expr/function.h"
#include "sillage/paving/sivia.h"

namespace sillage {

// Alg. 1 with [f] = f.eval_vector; f.nb_vars() == x0.size() and
// f.image_dim() == y.size() (else DimensionError).
Paving sivia(const IntervalVector& x0, const Function& f, const IntervalVector& y, double eps,
             const SiviaOptions& options = {});
// SIVIA (Alg. 1) for a scalar f: paving of x0 for X = f^-1([y]).
Paving sivia(const IntervalVector& x0, const Function& f, const Interval& y, double eps,
             const SiviaOptions& options = {});

// Alg. 1 coupled with a contractor, as in sivia.h (thesis Fig. 2.13).
Paving sivia(const IntervalVector& x0, const Function& f, const IntervalVector& y, const Ctc& ctc, double eps,
             const SiviaOptions& options = {});

// Alg. 2 for the interval function [f](x) = [f_lo(x), f_hi(x)] (2.42), with
// f_lo <= f_hi: X = { x : 0 ∈ [f_lo(x), f_hi(x)] }. Same variables, same
// image dimension for both (else DimensionError).
Paving kernel_sivia(const IntervalVector& x0, const Function& f_lo, const Function& f_hi, double eps,
                    const SiviaOptions& options = {});

// The same keeping the paving so far when the budget is spent or the run
// cancelled (SiviaResult, sivia.h).
SiviaResult sivia_run(const IntervalVector& x0, const Function& f, const IntervalVector& y, double eps,
                      const SiviaOptions& options = {});
SiviaResult sivia_run(const IntervalVector& x0, const Function& f, const Interval& y, double eps,
                      const SiviaOptions& options = {});
SiviaResult sivia_run(const IntervalVector& x0, const Function& f, const IntervalVector& y, const Ctc& ctc,
                      double eps, const SiviaOptions& options = {});
SiviaResult kernel_sivia_run(const IntervalVector& x0, const Function& f_lo, const Function& f_hi, double eps,
                             const SiviaOptions& options = {});

}  // namespace sillage
