#include "sillage/paving/sivia_function.h"

#include <string>

#include "sillage/ctc/definition_check.h"
#include "sillage/paving/paving_builder.h"

namespace sillage {

namespace {

// Alg. 1 with [f] = f.eval_vector; `ctc`, if given, contracts the undetermined boxes.
SiviaResult sivia_impl(const IntervalVector& x0, const Function& f, const IntervalVector& y, const Ctc* ctc,
                  double eps, const SiviaOptions& options) {
  check_same_size(f.nb_vars(), x0.size(), "sivia (nb_vars of f vs initial box)");
  check_same_size(f.image_dim(), y.size(), "sivia (image_dim of f vs Y)");
  if (ctc) check_same_size(ctc->nb_vars(), x0.size(), "sivia (contractor: nb_vars vs initial box)");
  const DefinitionCheck defined(f);
  auto test = [&](IntervalVector& x_in, IntervalVector& x_out) {
    const IntervalVector fx = f.eval_vector(x_in);
    // Inner needs f defined on the whole box: checked only when it matters.
    const bool inner = fx.is_subset(y) && defined.defined_on(x_in);
    detail::image_test(fx, y, inner, x_in, x_out, "sivia");
    if (ctc && !x_in.is_empty() && !x_out.is_empty()) ctc->contract(x_out);
  };
  return detail::run_paving(x0, eps, test, options.parallel, options.budget, "sivia");
}

}  // namespace

SiviaResult sivia_run(const IntervalVector& x0, const Function& f, const IntervalVector& y, double eps,
                      const SiviaOptions& options) {
  return sivia_impl(x0, f, y, nullptr, eps, options);
}

SiviaResult sivia_run(const IntervalVector& x0, const Function& f, const IntervalVector& y, const Ctc& ctc,
                      double eps, const SiviaOptions& options) {
  return sivia_impl(x0, f, y, &ctc, eps, options);
}

SiviaResult sivia_run(const IntervalVector& x0, const Function& f, const Interval& y, double eps,
                      const SiviaOptions& options) {
  return sivia_run(x0, f, IntervalVector{y}, eps, options);
}

SiviaResult kernel_sivia_run(const IntervalVector& x0, const Function& f_lo, const Function& f_hi, double eps,
                             const SiviaOptions& options) {
  check_same_size(f_lo.nb_vars(), x0.size(), "kernel_sivia (nb_vars of f_lo vs initial box)");
  check_same_size(f_hi.nb_vars(), x0.size(), "kernel_sivia (nb_vars of f_hi vs initial box)");
  check_same_size(f_lo.image_dim(), f_hi.image_dim(), "kernel_sivia (image_dim of f_lo vs f_hi)");
  const DefinitionCheck lo_defined(f_lo), hi_defined(f_hi);
  auto test = [&](IntervalVector& x_in, IntervalVector& x_out) {
    const IntervalVector lo = f_lo.eval_vector(x_in), hi = f_hi.eval_vector(x_in);
    const bool inner = lo_defined.defined_on(x_in) && hi_defined.defined_on(x_in);
    detail::kernel_test(lo, hi, inner, x_in, x_out, "kernel_sivia");
  };
  return detail::run_paving(x0, eps, test, options.parallel, options.budget, "kernel_sivia");
}

// The throwing forms: the paving of a finished run.

Paving sivia(const IntervalVector& x0, const Function& f, const IntervalVector& y, double eps,
             const SiviaOptions& options) {
  return sivia_run(x0, f, y, eps, options).take();
}

Paving sivia(const IntervalVector& x0, const Function& f, const IntervalVector& y, const Ctc& ctc, double eps,
             const SiviaOptions& options) {
  return sivia_run(x0, f, y, ctc, eps, options).take();
}

Paving sivia(const IntervalVector& x0, const Function& f, const Interval& y, double eps,
             const SiviaOptions& options) {
  return sivia_run(x0, f, y, eps, options).take();
}

Paving kernel_sivia(const IntervalVector& x0, const Function& f_lo, const Function& f_hi, double eps,
                    const SiviaOptions& options) {
  return kernel_sivia_run(x0, f_lo, f_hi, eps, options).take();
}

}  // namespace sillage
