// Decimal literals enclosed rigorously: strtod gives a double next to the number,
// an exact comparison of decimal digit strings tells on which side of it the
// real number lies.
#include "sillage/expr/literal.h"

#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <system_error>

#include "sillage/error.h"
#include "sillage/interval/rounding.h"

namespace sillage::detail {
namespace {

// A positive decimal 0.d1d2...dk x 10^exp with d1 != 0 and dk != 0
// (digits empty for zero).
struct Decimal {
  std::string digits;
  long exp = 0;
};

Decimal normalize(std::string digits, long exp) {
  std::size_t lead = 0;
  while (lead < digits.size() && digits[lead] == '0') ++lead;
  digits.erase(0, lead);
  exp -= static_cast<long>(lead);
  while (!digits.empty() && digits.back() == '0') digits.pop_back();
  if (digits.empty()) exp = 0;
  return {digits, exp};
}

// Parses the literal syntax; throws ParseError if malformed.
Decimal parse_decimal(std::string_view t) {
  std::string digits;
  std::size_t i = 0, int_digits = 0, frac_digits = 0;
  while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) digits += t[i++], ++int_digits;
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) digits += t[i++], ++frac_digits;
  }
  if (int_digits + frac_digits == 0) throw ParseError("invalid number literal \"" + std::string(t) + "\"");
  long e = 0;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    bool neg = false;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) neg = t[i++] == '-';
    if (i == t.size()) throw ParseError("invalid number literal \"" + std::string(t) + "\": missing exponent");
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) {
      e = std::min(e * 10 + (t[i++] - '0'), 100000000L);  // saturate: far beyond any double
    }
    if (neg) e = -e;
  }
  if (i != t.size()) throw ParseError("invalid number literal \"" + std::string(t) + "\"");
  return normalize(digits, e + static_cast<long>(int_digits));
}

// Exact decimal expansion of a positive finite double (at most 767 digits).
Decimal exact_decimal(double d) {
  char buf[900];
  auto r = std::to_chars(buf, buf + sizeof buf, d, std::chars_format::scientific, 800);
  std::string s(buf, r.ptr);
  const std::size_t epos = s.find('e');
  std::string digits = s.substr(0, 1) + s.substr(2, epos - 2);
  const long e = std::stol(s.substr(epos + 1));
  return normalize(digits, e + 1);
}

// Sign of a - b for two positive normalized decimals.
int compare(const Decimal& a, const Decimal& b) {
  if (a.digits.empty() || b.digits.empty()) return !a.digits.empty() - !b.digits.empty();
  if (a.exp != b.exp) return a.exp < b.exp ? -1 : 1;
  const int c = a.digits.compare(b.digits);
  return (c > 0) - (c < 0);
}

}  // namespace

Interval decimal_enclosure(std::string_view text) {
  const Decimal dec = parse_decimal(text);
  if (dec.digits.empty()) return Interval(0.0);
  // Fast path: value = N * 10^k with N < 10^15 and 10^|k| exact doubles; the
  // directed products/quotients are then the optimal enclosure.
  const long k = dec.exp - static_cast<long>(dec.digits.size());
  if (dec.digits.size() <= 15 && k >= -22 && k <= 22) {
    const double n = static_cast<double>(std::stoll(dec.digits));  // exact: < 2^53
    double p = 1;
    for (long i = 0; i < (k < 0 ? -k : k); ++i) p *= 10;  // exact up to 10^22
    if (k >= 0) return Interval(rounding::mul_down(n, p), rounding::mul_up(n, p));
    return Interval(rounding::div_down(n, p), rounding::div_up(n, p));
  }
  // strtod on an integer mantissa (no decimal point: locale-independent) and
  // a short exponent; glibc rounds correctly, subnormals included.
  const std::string norm =
      dec.digits + "e" + std::to_string(dec.exp - static_cast<long>(dec.digits.size()));
  const double d = std::strtod(norm.c_str(), nullptr);
  if (std::isinf(d)) return Interval::from_bounds_unchecked(rounding::kMax, rounding::kInf);
  if (d == 0) return Interval::from_bounds_unchecked(0.0, std::numeric_limits<double>::denorm_min());
  const int c = compare(dec, exact_decimal(d));
  if (c == 0) return Interval(d);
  return c < 0 ? Interval(rounding::next_down(d), d) : Interval(d, rounding::next_up(d));
}

namespace {

std::string bound_str(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 17);
  return std::string(buf, r.ptr);
}

// Shortest text (1 to 17 significant digits) of `x` whose enclosure is c.
bool plain_literal(const Interval& c, double x, std::string& out) {
  const bool neg = x < 0;
  const double a = std::fabs(x);
  for (int p = 1; p <= 17; ++p) {
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, a, std::chars_format::general, p);
    std::string s(buf, r.ptr);
    Interval e = decimal_enclosure(s);
    if (neg) e = -e;
    if (e == c) {
      out.clear();
      if (neg) out.push_back('-');
      out.append(s);
      return true;
    }
  }
  return false;
}

}  // namespace

std::string literal_str(const Interval& c) {
  if (c.is_empty()) return "[empty]";
  std::string s;
  if (c.is_bounded()) {
    if (plain_literal(c, c.lb(), s) || (!c.is_degenerate() && plain_literal(c, c.ub(), s))) return s;
  }
  if (c.is_degenerate()) return bound_str(c.lb());
  s.assign(1, '[');  // appends: GCC 12 warns falsely on "[" + std::string
  s.append(bound_str(c.lb())).append(", ").append(bound_str(c.ub())).append(1, ']');
  return s;
}

}  // namespace sillage::detail
