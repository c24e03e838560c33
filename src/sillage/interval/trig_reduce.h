#pragma once
// Private: rigorous reduction of a double modulo pi/2 (Payne-Hanek style, in
// exact integer arithmetic on 1280 bits of 2/pi). Used where libm cannot be
// trusted blindly: the quadrant of huge arguments, and sin/cos/tan values
// next to their zeros and poles, where the reduction cancels almost all bits
// (e.g. x = 6381956970095103 * 2^797, 2^-61 away from a multiple of pi/2,
// on which glibc 2.36's cos is 7 ulps off).

namespace sillage::detail {

struct Reduced {
  bool ok = false;   // false only if x was too close to a multiple of pi/2 to decide
  int quadrant = 0;  // floor(x / (pi/2)) mod 4
  int q = 0;         // x = q pi/2 + r with |r| <= pi/4: q mod 4
  // r = r_hi + r_lo (|r_lo| <= ulp(r_hi)/2) within a relative error of 2^-100.
  double r_hi = 0, r_lo = 0;
};

// x finite, |x| >= 1.
Reduced reduce_half_pi(double x);

}  // namespace sillage::detail
