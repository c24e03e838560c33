#include "sillage/paving/sivia.h"

#include <string>
#include <utility>

#include "sillage/paving/paving_builder.h"

namespace sillage {

namespace {

void require(bool callable, const char* where) {
  if (!callable) throw Error(std::string(where) + ": the function/contractor is empty");
}

}  // namespace

Paving SiviaResult::take() && {
  throw_unfinished(summary);
  return std::move(paving);
}

SiviaResult sivia_run(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y, double eps,
                      const SiviaOptions& options) {
  require(static_cast<bool>(f), "sivia");
  if (y.size() == 0) throw DimensionError("sivia: Y has dimension 0");
  auto test = [&](IntervalVector& x_in, IntervalVector& x_out) {
    detail::image_test(f(x_in), y, true, x_in, x_out, "sivia");
  };
  return detail::run_paving(x0, eps, test, options.parallel, options.budget, "sivia");
}

SiviaResult sivia_run(const IntervalVector& x0, const InclusionFunction& f, const Interval& y, double eps,
                      const SiviaOptions& options) {
  return sivia_run(x0, f, IntervalVector{y}, eps, options);
}

SiviaResult sivia_run(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y,
                      const ContractFunction& ctc, double eps, const SiviaOptions& options) {
  require(static_cast<bool>(f) && static_cast<bool>(ctc), "sivia (with contractor)");
  if (y.size() == 0) throw DimensionError("sivia: Y has dimension 0");
  auto test = [&](IntervalVector& x_in, IntervalVector& x_out) {
    detail::image_test(f(x_in), y, true, x_in, x_out, "sivia");
    if (!x_in.is_empty() && !x_out.is_empty()) ctc(x_out);  // undetermined: contract, then bisect
  };
  return detail::run_paving(x0, eps, test, options.parallel, options.budget, "sivia (with contractor)");
}

SiviaResult sivia_run(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y, const Ctc& ctc,
                      double eps, const SiviaOptions& options) {
  check_same_size(ctc.nb_vars(), x0.size(), "sivia (contractor: nb_vars vs initial box)");
  return sivia_run(x0, f, y, [&ctc](IntervalVector& x) { ctc.contract(x); }, eps, options);
}

SiviaResult sivia_separator_run(const IntervalVector& x0, const SeparateFunction& sep, double eps,
                                const SiviaOptions& options) {
  require(static_cast<bool>(sep), "sivia (separator)");
  return detail::run_paving(x0, eps, sep, options.parallel, options.budget, "sivia (separator)");
}

SiviaResult sivia_run(const IntervalVector& x0, const Sep& sep, double eps, const SiviaOptions& options) {
  check_same_size(sep.nb_vars(), x0.size(), "sivia (separator: nb_vars vs initial box)");
  return sivia_separator_run(
      x0, [&sep](IntervalVector& x_in, IntervalVector& x_out) { sep.separate(x_in, x_out); }, eps, options);
}

SiviaResult sivia_contractor_run(const IntervalVector& x0, const ContractFunction& ctc, double eps,
                                 const SiviaOptions& options) {
  require(static_cast<bool>(ctc), "sivia (contractor)");
  auto outer_only = [&ctc](IntervalVector& /*x_in*/, IntervalVector& x_out) { ctc(x_out); };
  return detail::run_paving(x0, eps, outer_only, options.parallel, options.budget, "sivia (contractor)");
}

SiviaResult sivia_run(const IntervalVector& x0, const Ctc& ctc, double eps, const SiviaOptions& options) {
  check_same_size(ctc.nb_vars(), x0.size(), "sivia (contractor: nb_vars vs initial box)");
  return sivia_contractor_run(x0, [&ctc](IntervalVector& x) { ctc.contract(x); }, eps, options);
}

SiviaResult kernel_sivia_run(const IntervalVector& x0, const KernelBounds& f, double eps,
                             const SiviaOptions& options) {
  require(static_cast<bool>(f), "kernel_sivia");
  auto test = [&](IntervalVector& x_in, IntervalVector& x_out) {
    const auto [lo, hi] = f(x_in);  // [f-]([x]), [f+]([x])
    detail::kernel_test(lo, hi, true, x_in, x_out, "kernel_sivia");
  };
  return detail::run_paving(x0, eps, test, options.parallel, options.budget, "kernel_sivia");
}

// The throwing forms: the paving of a finished run.

Paving sivia(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y, double eps,
             const SiviaOptions& options) {
  return sivia_run(x0, f, y, eps, options).take();
}

Paving sivia(const IntervalVector& x0, const InclusionFunction& f, const Interval& y, double eps,
             const SiviaOptions& options) {
  return sivia_run(x0, f, y, eps, options).take();
}

Paving sivia(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y,
             const ContractFunction& ctc, double eps, const SiviaOptions& options) {
  return sivia_run(x0, f, y, ctc, eps, options).take();
}

Paving sivia(const IntervalVector& x0, const InclusionFunction& f, const IntervalVector& y, const Ctc& ctc,
             double eps, const SiviaOptions& options) {
  return sivia_run(x0, f, y, ctc, eps, options).take();
}

Paving sivia_separator(const IntervalVector& x0, const SeparateFunction& sep, double eps,
                       const SiviaOptions& options) {
  return sivia_separator_run(x0, sep, eps, options).take();
}

Paving sivia(const IntervalVector& x0, const Sep& sep, double eps, const SiviaOptions& options) {
  return sivia_run(x0, sep, eps, options).take();
}

Paving sivia_contractor(const IntervalVector& x0, const ContractFunction& ctc, double eps,
                        const SiviaOptions& options) {
  return sivia_contractor_run(x0, ctc, eps, options).take();
}

Paving sivia(const IntervalVector& x0, const Ctc& ctc, double eps, const SiviaOptions& options) {
  return sivia_run(x0, ctc, eps, options).take();
}

Paving kernel_sivia(const IntervalVector& x0, const KernelBounds& f, double eps, const SiviaOptions& options) {
  return kernel_sivia_run(x0, f, eps, options).take();
}

}  // namespace sillage
