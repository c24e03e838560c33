// Reading a whole file with a size limit (read_file.h).
#include "sillage/read_file.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "sillage/error.h"

namespace sillage {

namespace {

// No set_max_file_bytes() yet: the environment or the default holds.
constexpr std::uint64_t kUnset = ~std::uint64_t{0};
std::atomic<std::uint64_t> g_limit{kUnset};

std::uint64_t limit_from_environment() {
  const char* v = std::getenv("SILLAGE_MAX_FILE_BYTES");
  if (v == nullptr || *v == '\0') return kDefaultMaxFileBytes;
  const char* end = v + std::strlen(v);
  std::uint64_t n = 0;
  const auto [p, ec] = std::from_chars(v, end, n);
  if (ec != std::errc() || p != end) {
    throw Error("SILLAGE_MAX_FILE_BYTES = '" + std::string(v) + "' is not a number of bytes (0: no limit)");
  }
  return n;
}

// "3000000000 bytes (2.8 GiB)": the exact count and a size one reads at a glance.
std::string bytes_text(std::uint64_t n) {
  std::string s = std::to_string(n) + " bytes";
  const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
  double x = static_cast<double>(n);
  int u = -1;
  while (x >= 1024 && u < 3) {
    x /= 1024;
    ++u;
  }
  if (u < 0) return s;
  char glance[32];
  std::snprintf(glance, sizeof glance, " (%.1f %s)", x, units[u]);
  return s + glance;
}

// `said`: how large the file is, against the limit.
Error too_large(const std::string& where, const std::string& said) {
  return Error(where + said + "; raise it with SILLAGE_MAX_FILE_BYTES=<bytes> or set_max_file_bytes(bytes) (0: no limit)");
}

}  // namespace

std::uint64_t max_file_bytes() {
  const std::uint64_t set = g_limit.load(std::memory_order_relaxed);
  return set != kUnset ? set : limit_from_environment();
}

void set_max_file_bytes(std::uint64_t bytes) { g_limit.store(std::min(bytes, kUnset - 1), std::memory_order_relaxed); }

std::string read_file_bytes(const std::string& path, const char* what, const char* expected) {
  namespace fs = std::filesystem;
  const std::string where = std::string(what) + ": '" + path + "'";
  std::error_code ec;
  const fs::file_type type = fs::status(path, ec).type();
  if (type == fs::file_type::not_found) throw Error(where + ": no such file");
  if (type == fs::file_type::directory) throw Error(where + " is a directory, not " + std::string(expected));
  if (type == fs::file_type::character || type == fs::file_type::block) {
    throw Error(where + " is a device, not " + std::string(expected) + " (a device may never end)");
  }
  const std::uint64_t limit = max_file_bytes();
  const bool regular = type == fs::file_type::regular;
  const std::uint64_t size = regular ? fs::file_size(path, ec) : 0;
  if (regular && !ec && limit != 0 && size > limit) {
    throw too_large(where, " is " + bytes_text(size) + ", more than the limit of " + bytes_text(limit));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(where + ": cannot open it for reading (permissions?)");
  // A regular file in one read (its size and one byte more, to see its end);
  // a pipe by pieces, never past the limit.
  std::string bytes;
  std::uint64_t piece = regular && !ec ? size + 1 : std::uint64_t{1} << 20;
  while (in) {
    const std::uint64_t at = bytes.size();
    if (limit != 0) piece = std::min(piece, limit + 1 - at);
    bytes.resize(at + piece);
    in.read(bytes.data() + at, static_cast<std::streamsize>(piece));
    bytes.resize(at + static_cast<std::uint64_t>(in.gcount()));
    if (limit != 0 && bytes.size() > limit) throw too_large(where, " holds more than " + bytes_text(limit) + ", the limit");
    piece = std::uint64_t{1} << 20;
  }
  if (in.bad()) throw Error(where + ": cannot read it");
  return bytes;
}

}  // namespace sillage
