#include "sillage/threads.h"

#include <string>

#include <tbb/global_control.h>

#include "sillage/error.h"

namespace sillage {

struct ThreadLimit::Control {
  tbb::global_control limit;
};

namespace {

std::size_t checked(std::size_t n) {
  if (n == 0) throw Error("ThreadLimit: the number of threads must be at least 1, got 0");
  return n;
}

}  // namespace

ThreadLimit::ThreadLimit(std::size_t n)
    : n_(checked(n)), control_(new Control{tbb::global_control(tbb::global_control::max_allowed_parallelism, n)}) {}

ThreadLimit::~ThreadLimit() = default;

std::size_t ThreadLimit::current() {
  return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
}

}  // namespace sillage
