#pragma once
// Set inversion via interval analysis (thesis 2.4): SIVIA (Alg. 1), its
// coupling with contractors and separators (2.4.3) and kernel SIVIA (Alg. 2).
// Every variant returns a Paving of the initial box x0 whose leaves are tagged
// Inner (proven in X), Outside (proven out of X) or Boundary (boxes of width
// < eps left undetermined), so that inner() ⊂ X ∩ x0 ⊂ outer().
//
// The callables may be called concurrently from several threads (unless
// options.parallel is false); the paving never depends on the thread count.
// x0 must be bounded, eps > 0 (else sillage::Error); an empty x0 gives an
// empty paving. See paving_builder.h for the bisection rule, and
// sivia_function.h for expression Functions (with a definition check).
//
// Each variant has two forms: sivia(...) returns the Paving and throws
// BudgetExceeded or Cancelled when options.budget is spent or cancelled;
// sivia_run(...) (kernel_sivia_run, sivia_separator_run, ...) returns a
// SiviaResult instead: the paving so far, whose boxes not yet classified are
// Boundary leaves, so that it is still an outer (and inner) approximation of
// X ∩ x0, with a Summary (outcome.h) saying how the run ended. A stopped or
// cancelled run in parallel depends on the scheduling (which boxes were
// refined first); a finished one never does.
#include <functional>
#include <utility>

#include "sillage/ctc/ctc.h"
#include "sillage/budget.h"
#include "sillage/ctc/sep.h"
#include "sillage/outcome.h"
#include "sillage/paving/paving.h"

namespace sillage {

// An inclusion function [f] : IR^n -> IR^m.
using InclusionFunction = std::function<IntervalVector(const IntervalVector&)>;
// Contracts a box in place (removing only points outside X).
using ContractFunction = std::function<void(IntervalVector&)>;
// Contracts x_in (removing points of X) and x_out (removing points out of X).
using SeparateFunction = std::function<void(IntervalVector& x_in, IntervalVector& x_out)>;
// For a box [x], the pair ([f-]([x]), [f+]([x])) of inclusion functions of the
// lower and upper bound functions f- and f+ of an interval function (2.42).
using KernelBounds = std::function<std::pair<IntervalVector, IntervalVector>(const IntervalVector&)>;

// Options of sivia and kernel_sivia.
struct SiviaOptions {
  bool parallel = true;  // grow subtrees as oneTBB tasks
  // Boxes (paving nodes), time and cancellation (budget.h): BudgetExceeded
  // or Cancelled is thrown when exhausted; 10^7 boxes by default.
  Budget budget;
};

// A SIVIA run: the paving and how the run ended.
struct SiviaResult {
  // The paving of x0, complete for Converged and NoSolution; for Stopped and
  // Cancelled the boxes not yet classified are Boundary leaves: still
  // inner() ⊂ X ∩ x0 ⊂ outer().
  Paving paving;
  // Converged; NoSolution when no leaf is Inner or Boundary (X ∩ x0 proven
  // empty, or x0 empty); Stopped (the budget in reason) or Cancelled.
  Summary summary;
  // The paving of a finished run; throws BudgetExceeded (Stopped) or
  // Cancelled (Cancelled), as sivia does.
  Paving take() &&;
};

// Alg. 1: X = f^-1(Y). A box is Outside when [f]([x]) ∩ Y = ∅, Inner when
// [f]([x]) ⊂ Y. With set-based (IEEE 1788) semantics Inner means: every point
// of [x] at which f is defined maps into Y.
Paving sivia(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y, double eps,
             const SiviaOptions& options = {});
Paving sivia(const IntervalVector& x0, const InclusionFunction& f, const Interval& y, double eps,
             const SiviaOptions& options = {});

// 2.4.3, Fig. 2.13: Alg. 1 coupled with a contractor of X: a box that the
// inclusion test leaves undetermined is contracted before it is bisected
// (line 8 of Alg. 1); what the contractor removes is tagged Outside.
Paving sivia(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y,
             const ContractFunction& ctc, double eps, const SiviaOptions& options = {});
Paving sivia(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y, const Ctc& ctc,
             double eps, const SiviaOptions& options = {});

// 2.4.3, with a separator: what the inner (outer) contractor removes is
// tagged Inner (Outside); the paving is no longer regular.
Paving sivia(const IntervalVector& x0, const Sep& sep, double eps, const SiviaOptions& options = {});
Paving sivia_separator(const IntervalVector& x0, const SeparateFunction& sep, double eps,
                       const SiviaOptions& options = {});

// 2.4.3, with a contractor only: an outer approximation (no Inner leaf).
Paving sivia(const IntervalVector& x0, const Ctc& ctc, double eps, const SiviaOptions& options = {});
Paving sivia_contractor(const IntervalVector& x0, const ContractFunction& ctc, double eps,
                        const SiviaOptions& options = {});

// Alg. 2: the kernel X = ker[f] = {x | 0 ∈ [f](x)} (2.41) of an interval
// function given by the bounds of (2.42). With [f^d] = [lb f-, ub f+] (2.44)
// and [f^c] = [ub f-, lb f+] (2.43): 0 ∉ [f^d]([x]) => Outside (the thesis'
// (2.46) writes f^c, a typo: only f^d proves exclusion); 0 ∈ [f^c]([x]) => Inner.
Paving kernel_sivia(const IntervalVector& x0, const KernelBounds& f, double eps, const SiviaOptions& options = {});

// The same variants keeping the paving so far when the budget is spent or
// the run cancelled (SiviaResult).
SiviaResult sivia_run(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y, double eps,
                      const SiviaOptions& options = {});
SiviaResult sivia_run(const IntervalVector& x0, const InclusionFunction& f, const Interval& y, double eps,
                      const SiviaOptions& options = {});
SiviaResult sivia_run(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y,
                      const ContractFunction& ctc, double eps, const SiviaOptions& options = {});
SiviaResult sivia_run(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y, const Ctc& ctc,
                      double eps, const SiviaOptions& options = {});
SiviaResult sivia_run(const IntervalVector& x0, const Sep& sep, double eps, const SiviaOptions& options = {});
SiviaResult sivia_separator_run(const IntervalVector& x0, const SeparateFunction& sep, double eps,
                                const SiviaOptions& options = {});
SiviaResult sivia_run(const IntervalVector& x0, const Ctc& ctc, double eps, const SiviaOptions& options = {});
SiviaResult sivia_contractor_run(const IntervalVector& x0, const ContractFunction& ctc, double eps,
                                 const SiviaOptions& options = {});
// Kernel SIVIA (Alg. 2) keeping the paving so far (SiviaResult).
SiviaResult kernel_sivia_run(const IntervalVector& x0, const KernelBounds& f, double eps,
                             const SiviaOptions& options = {});

}  // namespace sillage
