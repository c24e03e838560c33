#include "sillage/tube/tdomain_eval.h"

#include <algorithm>
#include <vector>

#include "sillage/tube/tube.h"

namespace sillage::detail {

namespace {

constexpr std::size_t kChunk = 256;  // the batch evaluator's chunk: its rows stay in cache

// (out[i]->*column)[k] = f(domain(k)) for k < count and each output i (the column is
// replaced), by chunks of kChunk appended from a buffer in cache.
template <class Domain>
void eval_elements(const Function& f, std::size_t count, Domain domain, std::span<TubeData* const> out,
                   TubeArray TubeData::*column) {
  Interval in[kChunk];
  const Interval* xs[1] = {in};
  std::vector<Interval> buffer(out.size() * kChunk);
  std::vector<Interval*> ys(out.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    ys[i] = buffer.data() + i * kChunk;
    (out[i]->*column).clear();
    (out[i]->*column).reserve(count);
  }
  for (std::size_t start = 0; start < count; start += kChunk) {
    const std::size_t c = std::min(kChunk, count - start);
    for (std::size_t j = 0; j < c; ++j) in[j] = domain(start + j);
    f.eval_batch(std::span<const Interval* const>(xs, 1), c, std::span<Interval* const>(ys));
    for (std::size_t i = 0; i < out.size(); ++i) {
      Interval* y = ys[i];
      for (std::size_t j = 0; j < c; ++j) y[j] = unknown_where_undefined(y[j]);
      TubeArray& v = out[i]->*column;
      v.insert(v.end(), y, y + c);
    }
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
