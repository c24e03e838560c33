#include "sillage/interval/rounding_policies.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

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

// SILLAGE_ROUNDING=portable forces the software path; unset, empty or "auto"
// takes the hardware when present. Another value is reported, not obeyed.
bool portable_forced() {
  const char* v = std::getenv("SILLAGE_ROUNDING");
  if (v == nullptr || *v == '\0' || std::strcmp(v, "auto") == 0) return false;
  if (std::strcmp(v, "portable") == 0) return true;
  std::fprintf(stderr, "sillage: SILLAGE_ROUNDING=%s is not 'portable' or 'auto'; using 'auto'\n", v);
  return false;
}

}  // namespace

// Constant-initialised to the software path, then set during static
// initialisation: any operation that runs earlier is exact all the same.
constinit std::atomic<bool> hardware_rounding_on{false};

namespace {
[[maybe_unused]] const bool chosen = [] {
  // The variable is read on every machine, so that a wrong value is reported
  // even where there is no hardware path to leave.
  const bool forced = portable_forced();
  hardware_rounding_on.store(hardware_rounding_available() && !forced, std::memory_order_relaxed);
  return true;
}();
}  // namespace

bool hardware_rounding_available() {
  static const bool available = detect();
  return available;
}

bool hardware_rounding() { return use_hardware_rounding(); }

void set_hardware_rounding(bool on) {
  hardware_rounding_on.store(on && hardware_rounding_available(), std::memory_order_relaxed);
}

}  // namespace sillage::detail
