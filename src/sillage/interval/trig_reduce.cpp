// Exact reduction modulo pi/2. With x = M 2^E (M a 53-bit integer),
// x 2/pi mod 4 only needs the bits of 2/pi of weight 2^(1-E) and below: bits
// of higher weight times M 2^E are multiples of 4. A 256-bit window of them
// times M gives x 2/pi mod 4 with an absolute error below 2^-200.
#include "sillage/interval/trig_reduce.h"

#include <cmath>
#include <cstdint>

#include "sillage/interval/rounding.h"

namespace sillage::detail {

namespace {

__extension__ typedef unsigned __int128 u128;

// 2/pi = 0.a1 a2 a3 ... in binary, 64 bits per word, most significant first
// (computed with MPFR; 1280 bits cover every binary64 exponent).
constexpr std::uint64_t kTwoOverPi[20] = {
    0xa2f9836e4e441529ULL, 0xfc2757d1f534ddc0ULL, 0xdb6295993c439041ULL, 0xfe5163abdebbc561ULL,
    0xb7246e3a424dd2e0ULL, 0x06492eea09d1921cULL, 0xfe1deb1cb129a73eULL, 0xe88235f52ebb4484ULL,
    0xe99c7026b45f7e41ULL, 0x3991d639835339f4ULL, 0x9c845f8bbdf9283bULL, 0x1ff897ffde05980fULL,
    0xef2f118b5a0a6d1fULL, 0x6d367ecf27cb09b7ULL, 0x4f463f669e5fea2dULL, 0x7527bac7ebe5f17bULL,
    0x3d0739f78a5292eaULL, 0x6bfb5fb11f8d5d08ULL, 0x56033046fc7b6babULL, 0xf0cfbc209af4361dULL};

// pi/2 = kHalfPiHi + kHalfPiLo + O(2^-107).
constexpr double kHalfPiHi = 0x1.921fb54442d18p+0, kHalfPiLo = 0x1.1a62633145c07p-54;

// The 64 bits a_s .. a_{s+63} of 2/pi.
std::uint64_t chunk(int s) {
  const int j = (s - 1) / 64, o = (s - 1) % 64;
  if (o == 0) return kTwoOverPi[j];
  return (kTwoOverPi[j] << o) | (kTwoOverPi[j + 1] >> (64 - o));
}

constexpr int kLimbs = 5;

struct U320 {
  std::uint64_t w[kLimbs] = {0, 0, 0, 0, 0};  // w[4] most significant
  int bit(int k) const { return static_cast<int>((w[k / 64] >> (k % 64)) & 1u); }
};

// Keeps the low n bits (n < 320).
U320 low_bits(U320 p, int n) {
  for (int i = 0; i < kLimbs; ++i) {
    const int lo = 64 * i;
    if (n <= lo) p.w[i] = 0;
    else if (n < lo + 64) p.w[i] &= (std::uint64_t{1} << (n - lo)) - 1;
  }
  return p;
}

// 2^n - f for 0 < f < 2^n (two's complement, kept to n bits).
U320 complement(const U320& f, int n) {
  U320 g;
  std::uint64_t borrow = 1;  // ~f + 1
  for (int i = 0; i < kLimbs; ++i) {
    const std::uint64_t v = ~f.w[i];
    g.w[i] = v + borrow;
    borrow = (borrow != 0 && g.w[i] == 0) ? 1 : 0;
  }
  return low_bits(g, n);
}

int leading_bit(const U320& p) {
  for (int i = kLimbs - 1; i >= 0; --i) {
    if (p.w[i] != 0) return 64 * i + 63 - __builtin_clzll(p.w[i]);
  }
  return -1;
}

U320 shift_left(const U320& p, int z) {
  U320 r;
  const int limbs = z / 64, bits = z % 64;
  for (int i = kLimbs - 1; i >= limbs; --i) {
    std::uint64_t v = p.w[i - limbs] << bits;
    if (bits != 0 && i - limbs - 1 >= 0) v |= p.w[i - limbs - 1] >> (64 - bits);
    r.w[i] = v;
  }
  return r;
}

}  // namespace

Reduced reduce_half_pi(double x) {
  Reduced out;
  int e = 0;
  const double m = std::frexp(std::fabs(x), &e);
  const auto M = static_cast<std::uint64_t>(std::ldexp(m, 53));
  const int E = e - 53;              // |x| = M 2^E, E >= -52 since |x| >= 1
  const int s = E >= 2 ? E - 1 : 1;  // first bit of 2/pi that matters
  const int sh = s + 255 - E;        // fraction bits of the product: 254 .. 308
  U320 p;
  u128 t = 0;
  for (int i = 0; i < 4; ++i) {  // M times the window, least significant word first
    t = static_cast<u128>(M) * chunk(s + 64 * (3 - i)) + (t >> 64);
    p.w[i] = static_cast<std::uint64_t>(t);
  }
  p.w[4] = static_cast<std::uint64_t>(t >> 64);
  // |x| 2/pi mod 4 = p 2^-sh: two integer bits, then the fraction f.
  int quadrant = 2 * p.bit(sh + 1) + p.bit(sh);
  const bool upper_half = p.bit(sh - 1) != 0;  // f >= 1/2: r = (f - 1) pi/2
  U320 g = low_bits(p, sh);
  if (upper_half) g = complement(g, sh);
  const int lead = leading_bit(g);
  // |g| >= 2^-80 keeps the window error below 2^-120 relative (no double
  // comes closer than 2^-62 to a multiple of pi/2 anyway).
  if (lead < 0 || lead - sh < -80) return out;
  const int z = 64 * kLimbs - 1 - lead;
  const U320 n = shift_left(g, z);
  const std::uint64_t top = n.w[kLimbs - 1], next = n.w[kLimbs - 2];
  const auto h1 = static_cast<double>(top >> 11);                          // 53 bits
  const auto h2 = static_cast<double>(((top & 0x7ffu) << 42) | (next >> 22));  // next 53
  const int base = 64 * kLimbs - sh - z;  // |g| = n 2^-(sh + z), n ~ top 2^(64 (kLimbs - 1))
  const double gh = std::ldexp(h1, base - 53), gl = std::ldexp(h2, base - 106);  // |g| to 2^-105
  // |r| = |g| pi/2 in double-double.
  const double prod = gh * kHalfPiHi;
  const double err = std::fma(gh, kHalfPiHi, -prod);
  const double tail = err + (gh * kHalfPiLo + gl * kHalfPiHi);
  double rh = prod + tail;
  double rl = tail - (rh - prod);  // Fast2Sum: |prod| >= |tail|
  int q = (quadrant + (upper_half ? 1 : 0)) & 3;
  if (upper_half != (x < 0)) {  // r < 0
    rh = -rh;
    rl = -rl;
  }
  if (x < 0) {  // x = -|x|: quadrants mirror, r changes sign
    q = (4 - q) & 3;
    quadrant = (3 - quadrant) & 3;  // floor(-y) = -floor(y) - 1 for non-integer y
  }
  out.ok = true;
  out.quadrant = quadrant;
  out.q = q;
  out.r_hi = rh;
  out.r_lo = rl;
  return out;
}

}  // namespace sillage::detail
