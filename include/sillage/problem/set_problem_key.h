#pragma once
// A problem file's text with the value of one key replaced (a bound swept by
// `sillage sweep`, a data path rewritten for a remote worker). Only the
// value's characters change: every other line and comment stays as written,
// so that the places in the messages of the new text are those of the file.
#include <string>

namespace sillage {

// The text with the value of `key` replaced by `value`, a TOML value as it
// would be written in the file (0.5, "[-1, 1]", [1, 2], { column = "r" }).
// key: names joined by dots, [i] for the element i (0-based) of an array:
// "constraint[8].time_error", "var.track.value", "data.odometry.file".
// ProblemError at file for a key that is not in the text (the keys there
// named), a value that is not one TOML value, or a text that is not TOML.
std::string set_problem_key(const std::string& text, const std::string& file, const std::string& key,
                            const std::string& value);

}  // namespace sillage
