#pragma once
// Direction of a temporal propagation along a tube (thesis 4.2.3): FORWARD
// carries information from t_0 towards t_N (Alg. 3), BACKWARD from t_N
// towards t_0 (Alg. 4), FWD_BWD both, forward first (Alg. 5). The values are
// bit flags: FORWARD | BACKWARD == FWD_BWD.

namespace sillage {

enum class TimePropag { FORWARD = 1, BACKWARD = 2, FWD_BWD = 3 };

constexpr TimePropag operator|(TimePropag a, TimePropag b) {
  return static_cast<TimePropag>(static_cast<int>(a) | static_cast<int>(b));
}

// True if p includes the direction d (e.g. has(FWD_BWD, FORWARD)).
constexpr bool has(TimePropag p, TimePropag d) { return (static_cast<int>(p) & static_cast<int>(d)) != 0; }

}  // namespace sillage
