#pragma once
// CtcDeriv's slice rule (slice_deriv.h) on 4 slices at a time, on the
// SoftRounding policy with AVX2 and FMA (internal header of the dynamics
// layer): δ[v] of a block of slices ahead of the sweeps' chains, the polygon
// hulls of a FWD_BWD sweep (the portable path's counterpart of
// polygon_hull_x8.h) and those of CtcEval's slices next to the gates it changed.
//
// Used on the portable rounding path where the CPU has AVX2 (avx2_rows()):
// the FWD_BWD sweep takes δ[v] of a block ahead of its chains of gates, then
// the hulls of the block, independent of each other. Each lane runs the
// scalar code's error-free transformations with the same instructions and
// operand order, so the results are those of scale, slice_hull and
// polygon_hull<SoftRounding> bit for bit (tested).
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "sillage/interval/arith_rows.h"
#include "sillage/interval/interval.h"
#include "sillage/tube/slice_deriv.h"

namespace sillage::detail {

// [plo[k - first], phi[k - first]] ⊇ δ_k [v](k), δ_k = t[k+1] - t[k], for
// k = first .. first+count-1, count a multiple of 4: scale<SoftRounding>(v[k],
// width<SoftRounding>(t[k], t[k+1])) of slice_deriv.h, bit for bit. v[k] not
// empty (an empty one gives meaningless values). Only call where
// avx2_rows() is true.
void scaled_derivatives_x4(const double* t, const Interval* v, std::size_t first, std::size_t count, double* plo,
                           double* phi);

// For k = first .. first+count-1 with count a multiple of 4: s[k] ∩= hull
// of the polygon of slice k, from the gates g[k], g[k+1] (final: consistent
// both ways and inside their slices), v[k] and the times t[k], t[k+1]. Only
// call where avx2_rows() is true. Returns nonzero if a slice changed.
std::uint64_t polygon_hulls_x4(const double* t, Interval* s, const Interval* g, const Interval* v, std::size_t first,
                               std::size_t count);

// The bounds polygon_hull<SoftRounding, false> gives for slices k = first ..
// first+count-1 (count a multiple of 4), from the gates g[k], g[k+1], v[k]
// and the times (CtcEval's hulls, which then meet them with the slices):
// lo[k - first], up[k - first]. Lanes with an empty gate or v get
// meaningless values. Only call where avx2_rows() is true.
void polygon_hull_bounds_x4(const double* t, const Interval* g, const Interval* v, std::size_t first,
                            std::size_t count, double* lo, double* up);

// [plo[k - first], phi[k - first]] ⊇ δ_k [v](k) for k = first ..
// first+count-1: scale<R> of slice_deriv.h, 4 at a time where the policy is
// SoftRounding and the CPU has AVX2 (the same bits), one at a time otherwise.
template <class R>
void scale_slices(const double* t, const Interval* v, std::size_t first, std::size_t count, double* plo,
                  double* phi) {
  std::size_t wide = 0;
  if constexpr (std::is_same_v<R, SoftRounding>) {
    if (avx2_rows()) {
      wide = count - count % 4;
      scaled_derivatives_x4(t, v, first, wide, plo, phi);
    }
  }
  for (std::size_t k = first + wide; k < first + count; ++k)
    scale<R>(v[k].lb(), v[k].ub(), width<R>(t[k], t[k + 1]), plo[k - first], phi[k - first]);
}

}  // namespace sillage::detail
