#include "sillage/budget.h"

#include <cstdio>
#include <utility>

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
  if (!try_add()) throw_unfinished(summary());
}

bool BudgetMeter::try_add() {
  const std::size_t now = boxes_.fetch_add(1, std::memory_order_relaxed) + 1;
  if (stopped()) return false;
  if (budget_.cancel.cancelled()) return stop(Status::Cancelled, std::string(where_) + ": cancelled");
  if (budget_.max_boxes != 0 && now > budget_.max_boxes) {
    // max_boxes + 1, not `now`: parallel tasks past the limit all stop, and
    // the message must not depend on which one is reported.
    return stop(Status::Stopped, std::string(where_) + ": budget exceeded: " + std::to_string(budget_.max_boxes + 1) +
                                     " " + unit_ + " > max_boxes = " + std::to_string(budget_.max_boxes) + "; raise " +
                                     option_ + ".max_boxes (0: no limit)" + hint_);
  }
  if (max_boxes_in_memory_ != 0 && now > max_boxes_in_memory_) {
    return stop(Status::Stopped, std::string(where_) + ": budget exceeded: " +
                                     std::to_string(max_boxes_in_memory_ + 1) + " boxes of " +
                                     std::to_string(bytes_per_box_) + " bytes > max_bytes = " +
                                     std::to_string(budget_.max_bytes) + "; raise " + option_ +
                                     ".max_bytes (0: no limit)" + hint_);
  }
  // The clock is read every 256 boxes only: it costs more than a box count.
  if (budget_.max_seconds > 0 && now % 256 == 0) {
    const double s = seconds();
    if (s > budget_.max_seconds) {
      char secs[32];
      std::snprintf(secs, sizeof secs, "%.2f", s);
      return stop(Status::Stopped, std::string(where_) + ": budget exceeded: " + secs + " s > max_seconds = " +
                                       number_text(budget_.max_seconds) + " (after " + std::to_string(now) + " " +
                                       unit_ + "); raise " + option_ + ".max_seconds (0: no limit)");
    }
  }
  if (budget_.progress && budget_.progress_every != 0 && now % budget_.progress_every == 0) report_progress();
  return true;
}

double BudgetMeter::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool BudgetMeter::stop(Status status, std::string reason) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!stopped_.load(std::memory_order_relaxed)) {  // the first reason holds
    status_ = status;
    reason_ = std::move(reason);
    stopped_.store(true, std::memory_order_release);
  }
  return false;
}

void BudgetMeter::report_progress() {
  // One call at a time, in order: the round and the work never decrease.
  const std::lock_guard<std::mutex> lock(mutex_);
  budget_.progress(Progress{where_, ++rounds_, boxes(), seconds()});
}

Summary BudgetMeter::summary() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return Summary{status_, reason_, rounds_, boxes(), seconds()};
}

void throw_unfinished(const Summary& summary) {
  if (summary.status == Status::Stopped) throw BudgetExceeded(summary.reason);
  if (summary.status == Status::Cancelled) {
    // The reason is Cancelled's message, "<where>: cancelled".
    const std::string suffix = ": cancelled";
    const std::string& r = summary.reason;
    const bool tail = r.size() >= suffix.size() && r.compare(r.size() - suffix.size(), suffix.size(), suffix) == 0;
    throw Cancelled(tail ? r.substr(0, r.size() - suffix.size()) : r);
  }
}

const char* status_name(Status s) {
  switch (s) {
    case Status::Converged: return "converged";
    case Status::Stopped: return "stopped";
    case Status::Cancelled: return "cancelled";
    case Status::NoSolution: return "no solution";
  }
  return "?";
}

std::string Summary::str() const {
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.3f", seconds);
  std::string s = std::string(status_name(status)) + " after " + std::to_string(work) + " units of work, " +
                  std::to_string(rounds) + " progress rounds, " + secs + " s";
  if (!reason.empty()) s += ": " + reason;
  return s;
}

}  // namespace sillage
