#pragma once
// One sweep of CtcDeriv's slice rule over slices first..last of raw arrays,
// for the local contraction of a network node (ctc_deriv_local.cpp); the
// same code as CtcDeriv::contract (ctc_deriv.cpp), rounding and blocks
// chosen the same way.
#include <cstddef>

#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"

namespace sillage::detail {

enum class DerivSweep {
  FwdBwdForward,   // FWD_BWD's first pass: the forward rule on the gates
  FwdBwdBackward,  // FWD_BWD's second pass: the backward rule and the polygons
};

// t: t_0 .. t_N; s, g: x's slices and gates; v: v's slices. Returns false if
// something is empty (x is then left for the caller to empty); `changed`
// accumulates whether a bound moved.
bool deriv_sweep(DerivSweep kind, const double* t, Interval* s, Interval* g, const Interval* v, std::size_t first,
                 std::size_t last, bool& changed);

// DimensionError (naming `where`) if x and v are not on the same TDomain.
void check_deriv_pair(const Tube& x, const Tube& v, const char* where);
// Error (naming `where`) if x is an angle tube (Tube::is_angle): CtcDerivAngle's.
void check_real(const Tube& x, const char* where);
// Error (naming `where`) unless first <= last < n.
void check_deriv_range(std::size_t n, std::size_t first, std::size_t last, const char* where);

}  // namespace sillage::detail
