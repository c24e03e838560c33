#include "sillage/budget.h"

#include <cstdio>

namespace sillage {

void check_budget(const Budget& budget, const char* where) {
  if (!(budget.max_seconds >= 0)) {
    throw Error(std::string(where) + ": budget.max_seconds must be >= 0 (0: no limit), got " +
                number_text(budget.max_seconds));
  }
}

BudgetMeter::BudgetMeter(const Budget& budget, const char* where, const char* option, const char* hint,
                         std::size_t bytes_per_box, const char* unit)
    : budget_(budget),
      where_(where),
      option_(option),
      hint_(hint),
      bytes_per_box_(bytes_per_box),
      unit_(unit),
      max_boxes_in_memory_(bytes_per_box > 0 && budget.max_bytes > 0 ? budget.max_bytes / bytes_per_box : 0),
      start_(std::chrono::steady_clock::now()) {
  check_budget(budget, where);
  if (bytes_per_box > 0 && budget.max_bytes > 0 && max_boxes_in_memory_ == 0) {
    throw Error(std::string(where) + ": budget.max_bytes = " + std::to_string(budget.max_bytes) +
                " holds no box of " + std::to_string(bytes_per_box) + " bytes");
  }
}

void BudgetMeter::add() {
  const std::size_t now = boxes_.fetch_add(1, std::memory_order_relaxed) + 1;
  if (budget_.cancel.cancelled()) throw Cancelled(where_);
  if (budget_.max_boxes != 0 && now > budget_.max_boxes) {
    // max_boxes + 1, not `now`: parallel tasks past the limit all throw, and
    // the message must not depend on which one is reported.
    throw BudgetExceeded(std::string(where_) + ": budget exceeded: " + std::to_string(budget_.max_boxes + 1) +
                         " " + unit_ + " > max_boxes = " + std::to_string(budget_.max_boxes) + "; raise " + option_ +
                         ".max_boxes (0: no limit)" + hint_);
  }
  if (max_boxes_in_memory_ != 0 && now > max_boxes_in_memory_) {
    throw BudgetExceeded(std::string(where_) + ": budget exceeded: " + std::to_string(max_boxes_in_memory_ + 1) +
                         " boxes of " + std::to_string(bytes_per_box_) + " bytes > max_bytes = " +
                         std::to_string(budget_.max_bytes) + "; raise " + option_ + ".max_bytes (0: no limit)" +
                         hint_);
  }
  // The clock is read every 256 boxes only: it costs more than a box count.
  if (budget_.max_seconds > 0 && now % 256 == 0) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (s > budget_.max_seconds) {
      char secs[32];
      std::snprintf(secs, sizeof secs, "%.2f", s);
      throw BudgetExceeded(std::string(where_) + ": budget exceeded: " + secs + " s > max_seconds = " +
                           number_text(budget_.max_seconds) + " (after " + std::to_string(now) + " " + unit_ + "); raise " +
                           option_ + ".max_seconds (0: no limit)");
    }
  }
}

}  // namespace sillage
