#pragma once
// The HC4-revise of a Function on up to kMaxBoxes boxes held in the rows of
// its tape (internal header of the expression layer): the caller writes the
// variables straight into their rows and reads the contracted values back
// from them, where Function::hc4_revise_batch copies its columns in and out.
// The pointwise tube contractor (tube/time_box_ctc.cpp) gathers slices and
// gates this way; hc4_revise_batch is written on it (the same results).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sillage/expr/function.h"

namespace sillage::detail {

class Tape;

class Hc4Rows {
 public:
  static constexpr std::size_t kMaxBoxes = 128;  // a chunk's rows stay in cache

  // The rows of f's tape for up to kMaxBoxes boxes: a buffer of the thread,
  // reused from call to call, or one of its own while another Hc4Rows of
  // the thread holds that one (a contractor calling another inside). Used
  // by one thread.
  explicit Hc4Rows(const Function& f);
  ~Hc4Rows();
  Hc4Rows(const Hc4Rows&) = delete;
  Hc4Rows& operator=(const Hc4Rows&) = delete;

  // Where the caller writes variable i of boxes 0 .. count-1 (count <=
  // kMaxBoxes, the same count for every variable of one contraction).
  Interval* var_row(std::size_t i, std::size_t count) const;

  // Contracts the `count` boxes written in the variables' rows so that f(x)
  // ∈ y: the rows then hold the contracted boxes (subsets of what was
  // written), and ok[j] = 0 where box j is proven empty (an empty variable
  // written in, or an empty y, make it so); its rows are then meaningless.
  void contract(std::size_t count, const IntervalVector& y, std::uint8_t* ok) const;

 private:
  const Tape& tape_;
  bool shared_;                // rows_ is the thread's buffer
  std::vector<Interval> own_;  // the rows when it is not
  Interval* rows_;
};

}  // namespace sillage::detail
