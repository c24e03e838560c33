#pragma once
// Cancelling a token from another thread while a computation runs, and how
// long the computation took to stop after it (tests of cancellation).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "sillage/budget.h"

namespace sillage::test {

// Runs `run`, which must throw Cancelled, while another thread cancels
// `token` after `delay`; returns the seconds from the cancel to the end of
// `run` (a test failure if it did not throw Cancelled).
template <class Run>
double seconds_to_stop(const CancelToken& token, std::chrono::milliseconds delay, Run run) {
  using clock = std::chrono::steady_clock;
  std::atomic<clock::time_point> cancelled_at{clock::time_point::max()};
  std::thread canceller([&] {
    std::this_thread::sleep_for(delay);
    cancelled_at = clock::now();
    token.cancel();
  });
  bool stopped = false;
  try {
    run();
  } catch (const Cancelled&) {
    stopped = true;
  }
  const clock::time_point end = clock::now();
  canceller.join();
  EXPECT_TRUE(stopped) << "not cancelled";
  return std::chrono::duration<double>(end - cancelled_at.load()).count();
}

}  // namespace sillage::test
