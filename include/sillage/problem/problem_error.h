#pragma once
// Errors of a problem file (sillage/problem): every message starts with
// "file:line:column: " and says what was found and what was expected.
#include <string>

#include "sillage/error.h"

namespace sillage {

// A place in a problem file (1-based line and column; 0 when unknown).
struct SourcePos {
  std::string file;
  int line = 0, column = 0;
  // "problem.toml:12:5" ("problem.toml" alone when the line is unknown).
  std::string str() const;
};

class ProblemError : public ParseError {
 public:
  // "file:line:col: found <found>, expected <expected>".
  ProblemError(const SourcePos& pos, const std::string& found, const std::string& expected);
  // "file:line:col: <message>", for errors that are not a found/expected pair.
  ProblemError(const SourcePos& pos, const std::string& message);
  const SourcePos& pos() const { return pos_; }

 private:
  SourcePos pos_;
};

}  // namespace sillage
