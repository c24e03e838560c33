#pragma once
// UTF-8 in error messages: they must decode (Python raises them as str),
// quote user data briefly, and give columns in characters, not bytes.
#include <cstddef>
#include <string>

namespace sillage::detail {

// Length of the valid UTF-8 sequence starting at text[i] (1 to 4), 0 if the
// bytes there are not valid UTF-8 (overlong forms and surrogates included).
std::size_t utf8_sequence_length(const std::string& text, std::size_t i);

// `text` with every byte that is not part of valid UTF-8 replaced by U+FFFD.
std::string valid_utf8(const std::string& text);

// `text` (made valid UTF-8) if it has at most max_chars characters, else its
// first max_chars characters and "...".
std::string quote_text(const std::string& text, std::size_t max_chars = 60);

// The characters of `text` around the 1-based character column `col` (about
// 60 of them), "..." marking what is cut: long texts quoted near an error.
std::string excerpt(const std::string& text, std::size_t col);

// "U+00E9".
std::string code_point_name(const std::string& sequence);

}  // namespace sillage::detail
