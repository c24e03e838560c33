#pragma once
// Reading a whole file named by a path, for every reader of the library (CSV
// tables, tube files, problem files). A wrong path must give an error, not
// exhaust the memory: a file larger than max_file_bytes() is refused before it
// is read, a pipe is read up to the limit only, and a device (/dev/zero,
// /dev/urandom, a terminal: no end, or no size) is refused.
//
// The limit is 2 GiB by default. The environment variable
// SILLAGE_MAX_FILE_BYTES (a number of bytes, 0: no limit) sets it for the
// process, set_max_file_bytes() from the program.
#include <cstdint>
#include <string>

namespace sillage {

// The default limit of a file read: 2 GiB.
inline constexpr std::uint64_t kDefaultMaxFileBytes = std::uint64_t{1} << 31;

// The largest file the readers accept, in bytes (0: no limit): the last
// set_max_file_bytes(), else SILLAGE_MAX_FILE_BYTES, else 2 GiB. Error if
// SILLAGE_MAX_FILE_BYTES is not a number of bytes.
std::uint64_t max_file_bytes();
// Sets max_file_bytes() for the whole process (0: no limit); thread-safe.
void set_max_file_bytes(std::uint64_t bytes);

// The bytes of the file at `path`. Messages start with `what` (the reader:
// "CsvTable::read", "load tube") and name the file; `expected` says what the
// file should be ("a CSV file"). Error if the path does not exist, is a
// directory or a device, cannot be read, or is larger than max_file_bytes()
// (the message gives its size, or "more than N bytes" for a pipe, and the limit).
std::string read_file_bytes(const std::string& path, const char* what, const char* expected = "a file");

}  // namespace sillage
