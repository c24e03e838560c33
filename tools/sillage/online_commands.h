#pragma once
// sillage stream and sillage replay (docs/online.md): a problem file run online.
#include <optional>
#include <string>

namespace sillage::cli {

// Rows as JSON Lines on stdin, estimates as JSON Lines on stdout; a bad line
// is an error line on stderr naming it and the stream goes on (strict: stops,
// exit status 2). window: seconds (none: the file's [online]).
int stream(const std::string& file, bool strict, std::optional<double> window);

// The file's own tables fed in stamp order (speed × real time, 0: as fast as
// possible); writes DIR/replay.html, online.jsonl, replay.json and replay.svg.
int replay(const std::string& file, std::string out, double speed, std::optional<double> window, bool batch, bool quiet);

}  // namespace sillage::cli
