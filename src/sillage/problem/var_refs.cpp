#include "sillage/problem/var_refs.h"

#include <cctype>

#include "sillage/expr/parser.h"

namespace sillage::detail {

namespace {

bool is_id_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_id_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::size_t parse_column(const std::string& message) {
  const std::string key = "at column ";
  const auto p = message.find(key);
  if (p == std::string::npos) return 0;
  std::size_t col = 0;
  for (std::size_t i = p + key.size(); i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])); ++i)
    col = col * 10 + static_cast<std::size_t>(message[i] - '0');
  return col > 0 ? col - 1 : 0;
}

}  // namespace

SourcePos shifted(const SourcePos& pos, std::size_t offset) {
  SourcePos p = pos;
  if (p.line > 0) p.column += static_cast<int>(offset);
  return p;
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
      out.text.append(text, i, j - i);
      i = j;
      continue;
    }
    if (!is_id_start(c)) {
      out.text += c;
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
      out.text += name;
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
    out.text += ref.id;
    i = j;
  }
  try {
    (void)parse_exprs(out.ids(), out.text);
  } catch (const ParseError& e) {
    // The rewritten text is longer than the written one past each x[i]: the
    // column is the parser's, mapped back only when nothing was rewritten.
    const std::size_t col = out.text == text ? parse_column(e.what()) : 0;
    throw ProblemError(shifted(pos, col), std::string("an expression the parser rejects: ") + e.what(),
                       "a valid expression (docs/cli.md)");
  }
  return out;
}

}  // namespace sillage::detail
