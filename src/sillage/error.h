#pragma once
// Errors of sillage: invalid input throws a subclass of sillage::Error whose
// message says what is wrong and where. An empty set is a result, not an error.
#include <stdexcept>
#include <string>

namespace sillage {

class Error : public std::invalid_argument {
 public:
  explicit Error(const std::string& what) : std::invalid_argument(what) {}
};

// Sizes that do not agree (box dimensions, matrix shapes, argument counts).
class DimensionError : public Error {
 public:
  using Error::Error;
};

// A text that cannot be parsed (expressions, data files).
class ParseError : public Error {
 public:
  using Error::Error;
};

// A double in full precision (17 significant digits), for error messages.
std::string number_text(double x);

}  // namespace sillage
