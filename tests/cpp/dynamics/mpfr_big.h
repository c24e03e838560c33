#pragma once
// A 256-bit MPFR number with RAII, and the exact check that an interval
// encloses one (the references of the CtcIvp tests).
#include <gtest/gtest.h>
#include <mpfr.h>

#include "sillage/interval/interval.h"

namespace mpfr_ref {

constexpr mpfr_prec_t kBits = 256;

struct Big {
  mpfr_t v;
  Big() { mpfr_init2(v, kBits); mpfr_set_zero(v, 1); }
  explicit Big(double d) { mpfr_init2(v, kBits); mpfr_set_d(v, d, MPFR_RNDN); }
  Big(const Big& o) { mpfr_init2(v, kBits); mpfr_set(v, o.v, MPFR_RNDN); }
  Big& operator=(const Big& o) { mpfr_set(v, o.v, MPFR_RNDN); return *this; }
  ~Big() { mpfr_clear(v); }
};

// The exact value is in x (its bounds compared with the 256-bit value).
inline ::testing::AssertionResult encloses(const sillage::Interval& x, const Big& exact) {
  if (mpfr_cmp_d(exact.v, x.lb()) >= 0 && mpfr_cmp_d(exact.v, x.ub()) <= 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << x << " misses " << mpfr_get_d(exact.v, MPFR_RNDN);
}

}  // namespace mpfr_ref
