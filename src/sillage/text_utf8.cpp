#include "sillage/text_utf8.h"

#include <cstdint>
#include <cstdio>

namespace sillage::detail {

std::size_t utf8_sequence_length(const std::string& s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<std::uint8_t>(s[i + k]); };
  const auto cont = [&](std::size_t k) { return i + k < s.size() && (b(k) & 0xC0) == 0x80; };
  if (i >= s.size()) return 0;
  const std::uint8_t c = b(0);
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return cont(1) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    if (!cont(1) || !cont(2)) return 0;
    if ((c == 0xE0 && b(1) < 0xA0) || (c == 0xED && b(1) >= 0xA0)) return 0;  // overlong, surrogate
    return 3;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    if (!cont(1) || !cont(2) || !cont(3)) return 0;
    if ((c == 0xF0 && b(1) < 0x90) || (c == 0xF4 && b(1) >= 0x90)) return 0;  // overlong, > U+10FFFF
    return 4;
  }
  return 0;
}

std::string valid_utf8(const std::string& text) {
  std::string r;
  r.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_sequence_length(text, i);
    if (n == 0) {
      r += "\xEF\xBF\xBD";  // U+FFFD
      ++i;
    } else {
      r.append(text, i, n);
      i += n;
    }
  }
  return r;
}

namespace {

// Byte offset of the character `chars` characters after byte i of valid UTF-8 t.
std::size_t advance(const std::string& t, std::size_t i, std::size_t chars) {
  for (; i < t.size() && chars > 0; --chars) i += utf8_sequence_length(t, i);
  return i;
}

}  // namespace

std::string quote_text(const std::string& text, std::size_t max_chars) {
  const std::string t = valid_utf8(text);
  const std::size_t end = advance(t, 0, max_chars);
  return end < t.size() ? t.substr(0, end) + "..." : t;
}

std::string excerpt(const std::string& text, std::size_t col) {
  constexpr std::size_t kBefore = 30, kAfter = 30;
  const std::string t = valid_utf8(text);
  const std::size_t first = advance(t, 0, col > kBefore + 1 ? col - 1 - kBefore : 0);
  const std::size_t last = advance(t, first, kBefore + kAfter);
  return (first > 0 ? "..." : "") + t.substr(first, last - first) + (last < t.size() ? "..." : "");
}

std::string code_point_name(const std::string& seq) {
  const auto b = [&](std::size_t k) { return static_cast<std::uint32_t>(static_cast<std::uint8_t>(seq[k])); };
  std::uint32_t cp = 0;
  switch (seq.size()) {
    case 1: cp = b(0); break;
    case 2: cp = ((b(0) & 0x1F) << 6) | (b(1) & 0x3F); break;
    case 3: cp = ((b(0) & 0x0F) << 12) | ((b(1) & 0x3F) << 6) | (b(2) & 0x3F); break;
    default: cp = ((b(0) & 0x07) << 18) | ((b(1) & 0x3F) << 12) | ((b(2) & 0x3F) << 6) | (b(3) & 0x3F);
  }
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(cp));
  return buf;
}

}  // namespace sillage::detail
