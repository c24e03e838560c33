#include "sillage/tube/tdomain_eval.h"

#include <algorithm>
#include <vector>

#include "sillage/tube/tube.h"

namespace sillage::detail {

namespace {

constexpr std::size_t kChunk = 256;  // the batch evaluator's chunk: its rows stay in cache

// out[i][k] = f(domain(k)) for k < count, by chunks of kChunk.
template <class Domain>
void eval_elements(const Function& f, std::size_t count, Domain domain, std::span<Interval* const> out) {
  Interval in[kChunk];
  const Interval* xs[1] = {in};
  std::vector<Interval*> ys(out.size());
  for (std::size_t start = 0; start < count; start += kChunk) {
    const std::size_t c = std::min(kChunk, count - start);
    for (std::size_t j = 0; j < c; ++j) in[j] = domain(start + j);
    for (std::size_t i = 0; i < out.size(); ++i) ys[i] = out[i] + start;
    f.eval_batch(std::span<const Interval* const>(xs, 1), c, std::span<Interval* const>(ys));
    for (Interval* y : ys)
      for (std::size_t j = 0; j < c; ++j) y[j] = unknown_where_undefined(y[j]);
  }
}

}  // namespace

void eval_into_tubes(const TDomain& td, const Function& f, std::span<Interval* const> slices,
                     std::span<Interval* const> gates) {
  const std::span<const double> t = td.times();  // finite and increasing; + 0.0: no -0 bound
  eval_elements(f, td.nb_slices(), [t](std::size_t k) { return Interval::from_bounds_unchecked(t[k] + 0.0, t[k + 1] + 0.0); },
                slices);
  eval_elements(f, td.nb_slices() + 1, [t](std::size_t k) { return Interval::from_bounds_unchecked(t[k] + 0.0, t[k] + 0.0); },
                gates);
}

}  // namespace sillage::detail
