#include "sillage/problem/problem_error.h"

namespace sillage {

std::string SourcePos::str() const {
  if (line <= 0) return file;
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

ProblemError::ProblemError(const SourcePos& pos, const std::string& found, const std::string& expected)
    : ParseError(pos.str() + ": found " + found + ", expected " + expected), pos_(pos) {}

ProblemError::ProblemError(const SourcePos& pos, const std::string& message)
    : ParseError(pos.str() + ": " + message), pos_(pos) {}

}  // namespace sillage
