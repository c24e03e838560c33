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

// A value of the wrong type where sillage expected another (a Python callable
// returning a str instead of a box, a lambda instead of a contractor).
class ArgumentTypeError : public Error {
 public:
  using Error::Error;
};

// An index or a time out of the valid range (a row, a slice, a component).
class OutOfRangeError : public Error {
 public:
  using Error::Error;
};

// A double in full precision (17 significant digits), for error messages.
std::string number_text(double x);

}  // namespace sillage
