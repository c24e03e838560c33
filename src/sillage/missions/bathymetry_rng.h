#pragma once
// The pseudo-random generator of the synthetic bathymetric mission: xoshiro256**
// seeded by splitmix64, with its own uniform distribution (53 random bits), so
// that a seed gives the same numbers on every platform and standard library
// (std::uniform_real_distribution is implementation-defined).
#include <cstdint>

namespace sillage::detail {

class BathymetryRng {
 public:
  explicit BathymetryRng(std::uint64_t seed);
  std::uint64_t next();                 // 64 random bits
  double uniform();                     // in [0, 1), a multiple of 2^-53
  double uniform(double lo, double hi); // in [lo, hi)
  // A generator for an independent stream (e.g. one per sensor), so adding
  // draws to one stream does not shift the others.
  BathymetryRng fork(std::uint64_t stream);

 private:
  std::uint64_t s_[4];
};

}  // namespace sillage::detail
