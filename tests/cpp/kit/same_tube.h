#pragma once
// Two tubes the same bit for bit, slice by slice and gate by gate (the
// failing element named), for tests that compare two ways of computing a tube.
#include <gtest/gtest.h>

#include "sillage/tube/tube.h"

#include "kit/same_bits.h"

namespace sillage::test {

inline void expect_same_bits(const Tube& a, const Tube& b) {
  ASSERT_EQ(a.nb_slices(), b.nb_slices());
  for (std::size_t k = 0; k < a.nb_slices(); ++k) ASSERT_TRUE(same_bits(a.slice(k), b.slice(k))) << "slice " << k;
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) ASSERT_TRUE(same_bits(a.gate(k), b.gate(k))) << "gate " << k;
}

}  // namespace sillage::test
