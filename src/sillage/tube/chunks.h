#pragma once
// Pointwise work over a tube's elements by chunks (internal header): the
// chunks are shared among the machine's threads (oneTBB) when there are
// enough of them to pay for the split. For work where each element depends
// on its own inputs alone, so that the results are the same for any number
// of threads.
#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace sillage::detail {

inline constexpr std::size_t kChunk = 256;  // the batch evaluator's chunk: its rows stay in cache
// From this many elements the chunks of costly work (an expression, sin,
// exp: 20 to 150 ns an element) are shared among threads: a chunk costs 5 to
// 40 µs, the split a few µs.
inline constexpr std::size_t kParallelFrom = 8 * kChunk;
// For copies and fills (1 to 2 ns an element once the pages are there; 20 to
// 25 ns where they are fresh, on a VM).
inline constexpr std::size_t kParallelCopyFrom = 1 << 16;

// run(begin, end) over [0, count) cut into pieces that begin on a multiple of
// kChunk; by several threads from parallel_from elements on.
template <class Run>
void for_chunks(std::size_t count, const Run& run, std::size_t parallel_from = kParallelFrom) {
  if (count < parallel_from) {
    run(std::size_t{0}, count);
    return;
  }
  const std::size_t chunks = (count + kChunk - 1) / kChunk;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 4), [&](const tbb::blocked_range<std::size_t>& r) {
    run(r.begin() * kChunk, std::min(count, r.end() * kChunk));
  });
}

}  // namespace sillage::detail
