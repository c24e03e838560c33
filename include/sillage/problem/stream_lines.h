#pragma once
// The JSON Lines of `sillage stream` (docs/online.md, "Stream format").
//
// In, one object per line: a row of a table,
//   {"table": "ranges", "t": 3900.1, "columns": {"t_s": 3900.0, "beacon_id": 2, "range_m": 17.3}}
// ("t": when it arrived; for a row of the clock table the end of its period),
// or a tick, time advancing without data: {"t": 3900.2}.
// Out, one object per update of the estimate:
//   {"t": 3900.2, "status": "converged", "window": [3840.2, 3900.2],
//    "p": [[lb, ub], [lb, ub]], "psi": [[lb, ub]]}
// bounds as the shortest decimals that read back as the same doubles, null
// for an infinite one; status "no solution" with "reason" when the data
// proved inconsistent.
#include <cstddef>
#include <string>

#include "sillage/problem/online_problem.h"

namespace sillage {

// The row a line gives; Error saying what is wrong (not JSON, not an object,
// an unknown key, a table or t of the wrong type, a column that is not a number).
StreamRow parse_stream_line(const std::string& line);

// The line of a row, as parse_stream_line reads it back (a producer's side:
// e.g. a log replayed into `sillage stream`); numbers round-trip exactly.
std::string stream_line(const StreamRow& row);

// The estimate of op at its current time, one line (no newline).
std::string estimate_line(const OnlineProblem& op);

}  // namespace sillage
