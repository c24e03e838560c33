#include "sillage/figures/text_width.h"

#include <cstring>

namespace sillage::detail {

namespace {

// Advance width of one character, in ems (DejaVu Sans, rounded up).
double em_width(unsigned char c) {
  if (c >= 0x80) return 0.9;  // the first byte of a non-ASCII character: wide, to be safe
  if (std::strchr(" .,:;'!|", c)) return 0.34;
  if (std::strchr("ijlftrI()[]{}", c)) return 0.42;
  if (std::strchr("mwMW@%", c)) return 1.0;
  if (std::strchr("=+<>~^#", c)) return 0.84;
  if (c >= 'A' && c <= 'Z') return 0.74;
  return 0.64;  // digits, other lower case letters and signs
}

}  // namespace

double text_width_px(const std::string& text, double size_px) {
  double ems = 0;
  for (unsigned char c : text) {
    if ((c & 0xC0) == 0x80) continue;  // UTF-8 continuation byte: the character is already counted
    ems += em_width(c);
  }
  return ems * size_px;
}

std::vector<std::string> wrap_text(const std::string& text, double size_px, double max_px) {
  std::vector<std::string> lines;
  std::string line;
  auto push_word = [&](std::string word) {
    const std::string joined = line.empty() ? word : line + " " + word;
    if (text_width_px(joined, size_px) <= max_px) {
      line = joined;
      return;
    }
    if (!line.empty()) lines.push_back(line);
    // A word too long for a line alone: cut it (whole UTF-8 characters) and mark the cut.
    if (text_width_px(word, size_px) > max_px) {
      while (!word.empty() && text_width_px(word + "…", size_px) > max_px) {
        while (!word.empty() && (static_cast<unsigned char>(word.back()) & 0xC0) == 0x80) word.pop_back();
        if (!word.empty()) word.pop_back();  // the lead byte (or an ASCII character)
      }
      word += "…";
    }
    line = word;
  };
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t j = text.find(' ', i);
    const std::string word = text.substr(i, j == std::string::npos ? std::string::npos : j - i);
    if (!word.empty()) push_word(word);
    if (j == std::string::npos) break;
    i = j + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace sillage::detail
