#pragma once
// Variable references in the expressions of a problem file: a scalar
// variable by its name (h), a component of a vector by name[i] (x[2],
// 0-based). rewrite_refs turns them into plain identifiers the expression
// parser accepts (x[2] -> x__2) and lists them in order of first appearance,
// which is the order of the Function's variables. An interval literal
// [a, b] is left alone: only a name directly followed by '[' is indexed.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sillage/problem/problem_error.h"

namespace sillage::detail {

struct VarRef {
  std::string var;
  std::size_t component = 0;
  bool indexed = false;  // written name[i]
  std::string id;        // the identifier in the rewritten text
};

struct RewrittenExpr {
  std::string text;
  std::vector<VarRef> refs;
  std::vector<std::string> ids() const;
};

// dim_of(name): the variable's dimension (1 for a scalar), nullopt if the
// name is not a variable; vector(name): true if it must be indexed.
// pos: the position of the expression's first character in the file.
// ProblemError for an unknown name, a missing or out-of-range index, and
// (after rewriting) a text the parser rejects.
RewrittenExpr rewrite_refs(const std::string& text, const SourcePos& pos,
                           const std::function<std::optional<std::size_t>(const std::string&)>& dim_of,
                           const std::function<bool(const std::string&)>& vector,
                           const std::string& known_text);

// pos moved `offset` characters to the right on its line.
SourcePos shifted(const SourcePos& pos, std::size_t offset);

// The error for an expression the parser rejects: `e` is the parser's error on
// `parsed`, which is `written` (the user's text, starting at pos) or its
// rewriting, origin[i] then being the byte of `written` that byte i of
// `parsed` comes from. The position moves to the column the parser names, the
// message quotes the user's text (never the rewritten one) and says what the
// parser found or wanted there; `what` names the expression ("the bound").
ProblemError rejected_expression(const SourcePos& pos, const std::string& what, const std::string& written,
                                 const std::string& parsed, const ParseError& e, const std::string& expected,
                                 const std::vector<std::size_t>& origin = {});

}  // namespace sillage::detail
