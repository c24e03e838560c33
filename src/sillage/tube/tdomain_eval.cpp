#include "sillage/tube/tdomain_eval.h"

#include <algorithm>
#include <vector>

#include "sillage/tube/chunks.h"
#include "sillage/tube/tube.h"

namespace sillage::detail {

namespace {

// (out[i]->*column)[k] = f(domain(k)) for k < count and each output i (the
// column is replaced). Each chunk is evaluated straight into the columns; the
// chunks are independent, so the values do not depend on how many threads
// share them.
template <class Domain>
void eval_elements(const Function& f, std::size_t count, Domain domain, std::span<TubeData* const> out,
                   TubeArray TubeData::*column) {
  for (TubeData* d : out) d->*column = unwritten_array<Interval>(count);
  const auto run = [&](std::size_t begin, std::size_t end) {
    Interval in[kChunk];
    const Interval* xs[1] = {in};
    std::vector<Interval*> ys(out.size());
    for (std::size_t start = begin; start < end; start += kChunk) {
      const std::size_t c = std::min(kChunk, end - start);
      for (std::size_t j = 0; j < c; ++j) in[j] = domain(start + j);
      for (std::size_t i = 0; i < out.size(); ++i) ys[i] = (out[i]->*column).data() + start;
      f.eval_batch(std::span<const Interval* const>(xs, 1), c, std::span<Interval* const>(ys));
      for (Interval* y : ys)
        for (std::size_t j = 0; j < c; ++j) y[j] = unknown_where_undefined(y[j]);
    }
  };
  try {
    for_chunks(count, run);
  } catch (...) {
    for (TubeData* d : out) (d->*column).clear();  // no element left unwritten
    throw;
  }
}

}  // namespace

void eval_into_tubes(const TDomain& td, const Function& f, std::span<TubeData* const> out) {
  const std::span<const double> t = td.times();  // finite and increasing; + 0.0: no -0 bound
  const std::size_t n = td.nb_slices();
  eval_elements(f, n, [t](std::size_t k) { return Interval::from_bounds_unchecked(t[k] + 0.0, t[k + 1] + 0.0); }, out,
                &TubeData::slices);
  eval_elements(f, n + 1, [t](std::size_t k) { return Interval::from_bounds_unchecked(t[k] + 0.0, t[k] + 0.0); }, out,
                &TubeData::gates);
}

}  // namespace sillage::detail
