#pragma once
// Interval +, −, ×, ÷, x² and √ over whole rows, four intervals at a time
// with AVX2 and FMA (internal header; arith_rows_avx2.cpp). The bounds are
// those of Interval's portable path (BranchFreeRounding in arith_kernels.h)
// bit for bit, signs of zero included: the same error-free transformations
// on the same operands, lane by lane, the sign cases as blends, the step to
// the next double as a 64-bit integer add. A block of four with a rare lane
// (a magnitude beyond 2^±968, the *_rare predicates) is redone by
// Interval's operators, whose exact fallback it needs; so is a tail below four.
// Directed rounding has one answer, so these are the AVX-512 path's bounds
// too (ArithRows.EqualOperatorsBitForBitOnEveryPath): the batch evaluator
// takes the rows on both paths.
//
// The library is compiled for AVX (-mfma) only: the code is compiled for
// AVX2 in its own file and runs only where the CPU has it (avx2_rows()).
#include <cstddef>
#include <cstdint>

#include "sillage/interval/interval.h"

namespace sillage::detail {

enum class RowOp : std::uint8_t { Add, Sub, Mul, Div, Sqr, Sqrt };

// An operand of a row: `count` intervals, or (constant) the interval *p for every row index.
struct RowArg {
  const Interval* p = nullptr;
  bool constant = false;
};

// True if the AVX2 rows (and the other AVX2 kernels of the portable path,
// such as slice_rule_x4.h) run: the CPU has AVX2 and FMA (checked once)
// and they are not turned off.
bool avx2_rows();
// Whether the CPU has them.
bool avx2_rows_available();
// Turns them off (or back on, where available): for tests comparing them
// with the one-interval-at-a-time path. Not thread-safe: set it while no
// other thread computes.
void set_avx2_rows(bool on);

// Whether a row of `count` intervals should take the AVX2 rows: not a short
// one (a box at a time, as the pointwise contractor with constants goes),
// where the inlined scalar kernels cost less than the call and the tail.
inline bool avx2_rows_for(std::size_t count) { return count >= 8 && avx2_rows(); }

// r[i] = a[i] op b[i] (op a[i] for x² and √; b unused) for i < count, the
// bounds of Interval's operators on the portable rounding path. r may be a
// or b. Call only where avx2_rows() is true.
void arith_rows_avx2(RowOp op, Interval* r, RowArg a, RowArg b, std::size_t count);

}  // namespace sillage::detail
