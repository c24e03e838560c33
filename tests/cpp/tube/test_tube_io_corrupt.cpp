// Corrupted tube files: whatever is wrong in the file, the error names it,
// and for bad time points says which one and its value.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <sstream>
#include <vector>

#include "kit/files.h"
#include "sillage/error.h"
#include "sillage/tube/tube_io.h"

using namespace sillage;

namespace {

// A TubeVector of 2 components over 5 slices, as a file's bytes.
std::string valid_bytes() {
  auto td = TDomain::create(std::vector<double>{0.0, 0.1, 0.5, 1.0, 1.5, 2.0});
  TubeVector x(td, "(t + [0, 1], [-1, 1] * t)");
  std::ostringstream os;
  save(x, os);
  return os.str();
}

constexpr std::size_t kTimes = 8 + 4 + 4 + 8;  // the first time point's byte
constexpr std::size_t kCount = kTimes + 6 * 8;  // the number of components' byte

void put_f64(std::string& s, std::size_t at, double x) { std::memcpy(&s[at], &x, 8); }
void put_u64(std::string& s, std::size_t at, std::uint64_t v) { std::memcpy(&s[at], &v, 8); }

std::string file_with(const std::string& bytes) { return test::temp_file("sillage_corrupt.tube", bytes); }

// The message of loading `bytes` from a file ("no error" if it loads).
std::string load_error(const std::string& bytes, std::shared_ptr<TDomain> td = nullptr) {
  const std::string path = file_with(bytes);
  return test::error_of([&] { load_tube_vector(path, td); });
}

}  // namespace

TEST(TubeIoCorrupt, BadTimePointsNameTheFileThePointAndItsValue) {
  const std::string path = file_with("");
  std::string nan_time = valid_bytes();
  put_f64(nan_time, kTimes + 2 * 8, std::nan(""));
  EXPECT_EQ(load_error(nan_time), "load tube: '" + path + "': time point 2 (byte " + std::to_string(kTimes + 16) +
                                      ") is nan, not a finite time");
  std::string decreasing = valid_bytes();
  put_f64(decreasing, kTimes + 3 * 8, 0.2);
  EXPECT_EQ(load_error(decreasing), "load tube: '" + path + "': time point 3 (byte " + std::to_string(kTimes + 24) +
                                        ") is 0.20000000000000001, not after time point 2 = 0.5");
  // Against a given TDomain: the first time point that differs.
  auto td = TDomain::create(std::vector<double>{0.0, 0.1, 0.5, 1.0, 1.5, 2.0});
  EXPECT_EQ(load_error(nan_time, td), "load tube: '" + path + "': time point 2 (byte " + std::to_string(kTimes + 16) +
                                          ") is nan, the given TDomain's is 0.5");
}

// Every mutation of a valid file (each time point, the counts, every
// truncation, random bytes) either loads or gives an error naming the file.
TEST(TubeIoCorrupt, EveryErrorNamesTheFile) {
  const std::string good = valid_bytes();
  std::vector<std::string> files;
  const double odd[] = {std::nan(""), INFINITY, -INFINITY, -1.0, 0.0, 0.3, 1e300};
  for (std::size_t k = 0; k < 6; ++k) {
    for (const double t : odd) {
      files.push_back(good);
      put_f64(files.back(), kTimes + 8 * k, t);
    }
  }
  for (const std::uint64_t nt : {0ull, 1ull, 2ull, 5ull, 7ull, 1ull << 31, ~0ull}) {
    files.push_back(good);
    put_u64(files.back(), kTimes - 8, nt);
  }
  for (const std::uint64_t n : {0ull, 1ull, 3ull, 1ull << 20, ~0ull}) {
    files.push_back(good);
    put_u64(files.back(), kCount, n);
  }
  for (std::size_t cut = 0; cut < good.size(); ++cut) files.push_back(good.substr(0, cut));
  files.push_back(good + "x");
  std::mt19937 rng(37);
  for (int i = 0; i < 2000; ++i) {
    std::string s = good;
    for (int j = 0, m = 1 + static_cast<int>(rng() % 3); j < m; ++j) s[rng() % s.size()] = static_cast<char>(rng());
    files.push_back(s);
  }
  const std::string path = file_with("");
  std::size_t errors = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string msg = load_error(files[i]);
    if (msg == "no error") continue;
    ++errors;
    EXPECT_NE(msg.find("'" + path + "'"), std::string::npos) << "mutation " << i << ": " << msg;
  }
  EXPECT_GT(errors, good.size());  // every truncation at least
}
