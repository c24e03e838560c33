#include "sillage/problem/var_refs.h"

#include <cctype>

#include "sillage/expr/parser.h"
#include "sillage/text_utf8.h"

namespace sillage::detail {

namespace {

bool is_id_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_id_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

constexpr const char* kAtColumn = " at column ";

// The parser's column (1-based, in characters) out of its message; 0 if none.
std::size_t parse_column(const std::string& message) {
  const auto p = message.find(kAtColumn);
  if (p == std::string::npos) return 0;
  std::size_t col = 0;
  for (std::size_t i = p + std::string(kAtColumn).size();
       i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])); ++i)
    col = col * 10 + static_cast<std::size_t>(message[i] - '0');
  return col;
}

bool continues_utf8(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// The byte where the character `chars` (0-based) of s starts (s.size() past the end).
std::size_t byte_of_char(const std::string& s, std::size_t chars) {
  std::size_t b = 0;
  for (std::size_t seen = 0; b < s.size(); ++b) {
    if (continues_utf8(s[b])) continue;
    if (seen++ == chars) return b;
  }
  return s.size();
}

// The number of characters of s before byte b.
std::size_t chars_before(const std::string& s, std::size_t b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < b && i < s.size(); ++i) n += !continues_utf8(s[i]);
  return n;
}

}  // namespace

SourcePos shifted(const SourcePos& pos, std::size_t offset) {
  SourcePos p = pos;
  if (p.line > 0) p.column += static_cast<int>(offset);
  return p;
}

ProblemError rejected_expression(const SourcePos& pos, const std::string& what, const std::string& written,
                                 const std::string& parsed, const ParseError& e, const std::string& expected,
                                 const std::vector<std::size_t>& origin) {
  const std::string message = e.what();
  const std::string reason = message.substr(0, message.find(kAtColumn));
  const std::string quoted = what + " \"" + quote_text(written, 200) + "\"";
  const std::size_t parser_col = parse_column(message);
  if (parser_col == 0) return ProblemError(pos, quoted + " (" + reason + ")", expected);
  const std::size_t b = byte_of_char(parsed, parser_col - 1);
  const std::size_t w = origin.empty() ? std::min(b, written.size()) : origin[std::min(b, origin.size() - 1)];
  const std::size_t col = chars_before(written, w);
  const std::string at = " at its column " + std::to_string(col + 1);
  const std::string wanted = "expected ";
  if (reason.compare(0, wanted.size(), wanted) == 0)  // "expected ')'": say what the text needs there
    return ProblemError(shifted(pos, col), quoted + ", which needs " + reason.substr(wanted.size()) + at, expected);
  return ProblemError(shifted(pos, col), quoted + " with " + reason + at, expected);
}

std::vector<std::string> RewrittenExpr::ids() const {
  std::vector<std::string> v;
  for (const VarRef& r : refs) v.push_back(r.id);
  return v;
}

RewrittenExpr rewrite_refs(const std::string& text, const SourcePos& pos,
                           const std::function<std::optional<std::size_t>(const std::string&)>& dim_of,
                           const std::function<bool(const std::string&)>& vector, const std::string& known_text) {
  RewrittenExpr out;
  std::vector<std::size_t> origin;  // byte of `text` each byte of out.text comes from
  const auto copy = [&](std::size_t from, std::size_t to) {  // text[from, to) as written
    out.text.append(text, from, to - from);
    for (std::size_t k = from; k < to; ++k) origin.push_back(k);
  };
  if (text.find_first_not_of(" \t") == std::string::npos)
    throw ProblemError(pos, "an empty expression", "an expression such as \"v[0] - 10*cos(x[2])\"");
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    // A number such as 1e5 or 2.5E-3: its letters are not names.
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < text.size() &&
                                                        std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
      std::size_t j = i;
      while (j < text.size() && (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.')) ++j;
      if (j < text.size() && (text[j] == 'e' || text[j] == 'E')) {
        std::size_t k = j + 1;
        if (k < text.size() && (text[k] == '+' || text[k] == '-')) ++k;
        if (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) {
          j = k;
          while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
        }
      }
      copy(i, j);
      i = j;
      continue;
    }
    if (!is_id_start(c)) {
      copy(i, i + 1);
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && is_id_char(text[j])) ++j;
    const std::string name = text.substr(i, j - i);
    std::size_t k = j;
    while (k < text.size() && text[k] == ' ') ++k;
    const bool call = k < text.size() && text[k] == '(';
    if (is_reserved_name(name) || call) {  // pi, inf, function names: the parser's business
      copy(i, j);
      i = j;
      continue;
    }
    const auto dim = dim_of(name);
    if (!dim)
      throw ProblemError(shifted(pos, i), "the unknown name '" + name + "'", "a variable or column (" + known_text + ")");
    VarRef ref{name, 0, false, name};
    if (j < text.size() && text[j] == '[') {
      std::size_t e = j + 1, index = 0;
      bool digits = false;
      while (e < text.size() && std::isdigit(static_cast<unsigned char>(text[e])) && e - j < 10) {
        index = index * 10 + static_cast<std::size_t>(text[e] - '0');
        digits = true;
        ++e;
      }
      if (!digits || e >= text.size() || text[e] != ']')
        throw ProblemError(shifted(pos, j), "'" + text.substr(j, std::min<std::size_t>(8, text.size() - j)) + "'",
                           "an index such as " + name + "[0]");
      if (index >= *dim)
        throw ProblemError(shifted(pos, j), "index " + std::to_string(index) + " of '" + name + "'",
                           "an index from 0 to " + std::to_string(*dim - 1) + " ('" + name + "' has dimension " +
                               std::to_string(*dim) + ")");
      ref = VarRef{name, index, true, name + "__" + std::to_string(index)};
      j = e + 1;
    } else if (vector(name)) {
      throw ProblemError(shifted(pos, i), "the vector '" + name + "' without an index",
                         "a component such as " + name + "[0]");
    }
    bool seen = false;
    for (const VarRef& r : out.refs) seen = seen || r.id == ref.id;
    if (!seen) out.refs.push_back(ref);
    out.text += ref.id;  // x__2 for x[2]: each of its bytes from the name's first
    origin.resize(out.text.size(), i);
    i = j;
  }
  try {
    (void)parse_exprs(out.ids(), out.text);
  } catch (const ParseError& e) {
    origin.push_back(text.size());  // the parser's column past the end: the end of the text
    throw rejected_expression(pos, "the expression", text, out.text, e, "a valid expression (docs/cli.md)", origin);
  }
  return out;
}

}  // namespace sillage::detail
