#include "sillage/figures/loop_style.h"

namespace sillage {

LoopStatus loop_status(const Loop& loop) {
  if (!loop.complete()) return LoopStatus::Partial;
  return loop.proven() ? LoopStatus::Proven : LoopStatus::Unproven;
}

std::string to_string(LoopStatus status) {
  switch (status) {
    case LoopStatus::Proven: return "proven";
    case LoopStatus::Unproven: return "unproven";
    case LoopStatus::Partial: return "partial";
  }
  return "?";
}

Style loop_style(LoopStatus status) {
  switch (status) {
    case LoopStatus::Proven: return {"#ff8c00", "#c25e00", 1.0, 0.45, "proven"};
    case LoopStatus::Unproven: return {"#000000", "#000000", 1.0, 0.45, "unproven"};
    case LoopStatus::Partial: return {"#9e9e9e", "#616161", 1.0, 0.45, "partial"};
  }
  return {};
}

}  // namespace sillage
