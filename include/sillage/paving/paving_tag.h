#pragma once
// PavingTag: what is known about a leaf box of a paving (thesis Fig. 2.11).
#include <cstdint>
#include <string>

namespace sillage {

enum class PavingTag : std::uint8_t {
  Inner = 0,     // proven inside X (green)
  Boundary = 1,  // undetermined at the precision eps (yellow)
  Outside = 2,   // proven outside X (blue)
};

inline std::string to_string(PavingTag tag) {
  switch (tag) {
    case PavingTag::Inner: return "Inner";
    case PavingTag::Boundary: return "Boundary";
    case PavingTag::Outside: return "Outside";
  }
  return "?";
}

}  // namespace sillage
