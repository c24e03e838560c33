#pragma once
// The polygon hull of CtcDeriv's slice rule (slice_deriv.h, polygon_hull with
// consistent gates and widening) on 8 slices at a time, with AVX-512F and
// static rounding modes (internal header of the dynamics layer).
//
// Used by the FWD_BWD sweep with hardware rounding: the backward pass first
// contracts the gates of a block of slices (a sequential chain), then this
// computes the hulls of the block, independent of each other. The results
// are bit for bit those of the scalar code with HardRounding (same
// instructions, same operand order in min/max), which the tests check.
#include <cstddef>
#include <cstdint>

#include "sillage/interval/rounding_policies.h"
#include "sillage/interval/interval.h"

namespace sillage::detail {

#if SILLAGE_HARD_ROUNDING
// For k = first .. first+count-1: s[k] ∩= hull of the polygon of slice k,
// from the gates g[k], g[k+1] (final: consistent both ways and inside their
// slices), v[k] and the times t[k], t[k+1]. Only call when
// hardware_rounding() is on (AVX-512F). Returns nonzero if a slice changed.
std::uint64_t polygon_hulls_x8(const double* t, Interval* s, const Interval* g, const Interval* v, std::size_t first,
                               std::size_t count);
#endif

}  // namespace sillage::detail
