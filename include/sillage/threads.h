#pragma once
// The threads of sillage's parallel work: SIVIA and its variants, the
// t-plane's components and proofs, the temporal SLAM's loops, and the
// pointwise work on large tubes (built from expressions, sin, exp... of a
// tube from 2048 slices; copies, constant tubes, operations with an interval
// from 65536). All of the machine's by default (oneTBB); the results never
// depend on their number.
#include <cstddef>
#include <memory>

namespace sillage {

// At most n threads for the parallel work started while this object lives,
// anywhere in the process (with several limits alive, the smallest one holds).
// Error if n is 0.
class ThreadLimit {
 public:
  explicit ThreadLimit(std::size_t n);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

  // The n of this limit.
  std::size_t threads() const { return n_; }
  // The number of threads the parallel work may use now.
  static std::size_t current();

 private:
  struct Control;  // the oneTBB global_control, kept out of this header
  std::size_t n_;
  std::unique_ptr<Control> control_;
};

}  // namespace sillage
