#include "sillage/interval/rounding_policies.h"

#include <atomic>

namespace sillage::detail {

namespace {

bool detect() {
#if SILLAGE_HARD_ROUNDING
  // libgcc / compiler-rt also check that the OS saves the AVX-512 state.
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f");
#else
  return false;
#endif
}

std::atomic<bool>& enabled() {
  static std::atomic<bool> on{detect()};
  return on;
}

}  // namespace

bool hardware_rounding_available() {
  static const bool available = detect();
  return available;
}

bool hardware_rounding() { return enabled().load(std::memory_order_relaxed); }

void set_hardware_rounding(bool on) { enabled().store(on && hardware_rounding_available(), std::memory_order_relaxed); }

}  // namespace sillage::detail
