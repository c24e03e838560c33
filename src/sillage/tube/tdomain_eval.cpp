#include "sillage/tube/tdomain_eval.h"

#include <algorithm>
#include <vector>

#include "sillage/tube/tube.h"

namespace sillage::detail {

namespace {

constexpr std::size_t kChunk = 256;  // the batch evaluator's chunk: its rows stay in cache

// Appends f(domain(k)) for k < count to *column(i) for each output i, by chunks of kChunk.
template <class Domain, class Column>
void eval_elements(const Function& f, std::size_t count, Domain domain, std::size_t m, Column column) {
  Interval in[kChunk];
  const Interval* xs[1] = {in};
  std::vector<Interval> buffer(m * kChunk);
  std::vector<Interval*> ys(m);
  for (std::size_t i = 0; i < m; ++i) {
    ys[i] = buffer.data() + i * kChunk;
    column(i)->reserve(count);
  }
  for (std::size_t start = 0; start < count; start += kChunk) {
    const std::size_t c = std::min(kChunk, count - start);
    for (std::size_t j = 0; j < c; ++j) in[j] = domain(start + j);
    f.eval_batch(std::span<const Interval* const>(xs, 1), c, std::span<Interval* const>(ys));
    for (std::size_t i = 0; i < m; ++i) {
      Interval* y = ys[i];
      for (std::size_t j = 0; j < c; ++j) y[j] = unknown_where_undefined(y[j]);
      column(i)->insert(column(i)->end(), y, y + c);
    }
  }
}

}  // namespace

void eval_into_tubes(const TDomain& td, const Function& f, std::span<TubeData* const> out) {
  const std::span<const double> t = td.times();  // finite and increasing; + 0.0: no -0 bound
  const std::size_t n = td.nb_slices(), m = out.size();
  for (TubeData* d : out) {
    d->slices.clear();
    d->gates.clear();
  }
  eval_elements(f, n, [t](std::size_t k) { return Interval::from_bounds_unchecked(t[k] + 0.0, t[k + 1] + 0.0); }, m,
                [out](std::size_t i) { return &out[i]->slices; });
  eval_elements(f, n + 1, [t](std::size_t k) { return Interval::from_bounds_unchecked(t[k] + 0.0, t[k] + 0.0); }, m,
                [out](std::size_t i) { return &out[i]->gates; });
}

}  // namespace sillage::detail
