// Binary serialization: round trips, and every kind of bad file rejected.
#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

#include "kit/files.h"
#include "sillage/error.h"
#include "sillage/tube/tube_io.h"

using namespace sillage;

namespace {

Tube sample_tube() {
  auto td = TDomain::create(std::vector<double>{0.0, 0.1, 0.5, 2.0});
  return Tube(td, {Interval(0, 1), Interval::empty(), Interval(-1, rounding::kInf)},
              {Interval(0.1, 0.2), Interval(0.3), Interval::all_reals(), Interval(-1e300, 5)});
}

std::string bytes_of(const Tube& x) {
  std::ostringstream os;
  save(x, os);
  return os.str();
}

}  // namespace

TEST(TubeIo, RoundTripTube) {
  const Tube x = sample_tube();
  const std::string s = bytes_of(x);
  EXPECT_EQ(s.size(), 8 + 4 + 4 + 8 + 4 * 8 + 8 + 7 * 16u);
  std::istringstream is(s);
  Tube y = load_tube(is);
  EXPECT_NE(y.tdomain(), x.tdomain());
  EXPECT_EQ(std::vector<double>(y.tdomain()->times().begin(), y.tdomain()->times().end()),
            std::vector<double>(x.tdomain()->times().begin(), x.tdomain()->times().end()));
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(y.slice(k), x.slice(k));
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(y.gate(k), x.gate(k));
  std::istringstream is2(s);
  Tube z = load_tube(is2, x.tdomain());  // attached to the given domain
  EXPECT_EQ(z, x);
}

TEST(TubeIo, RoundTripTubeVectorAndFile) {
  auto td = TDomain::create(0.0, 1.0, 0.25);
  TubeVector x(td, "(t, [1,2]*t)");
  const std::string path = testing::TempDir() + "/sillage_tube_io_test.bin";
  save(x, path);
  TubeVector y = load_tube_vector(path, td);
  EXPECT_EQ(y, x);
  EXPECT_THROW(load_tube(path), Error);  // a TubeVector, not a Tube
  EXPECT_THROW(load_tube("/nonexistent/dir/file.bin"), Error);
}

TEST(TubeIo, RejectsForeignAndTruncatedFiles) {
  const std::string s = bytes_of(sample_tube());
  {
    std::istringstream is("hello, this is not a tube file at all");
    EXPECT_THROW(load_tube(is), Error);
  }
  for (std::size_t cut : {0u, 5u, 8u, 14u, 20u, 30u, 70u, 100u}) {
    std::istringstream is(s.substr(0, std::min<std::size_t>(cut, s.size() - 1)));
    try {
      load_tube(is);
      FAIL() << "accepted a file truncated at " << cut;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
  }
  std::istringstream last(s.substr(0, s.size() - 1));
  EXPECT_THROW(load_tube(last), Error);
  std::string bad_version = s;
  bad_version[8] = 9;
  std::istringstream v(bad_version);
  EXPECT_THROW(load_tube(v), Error);
  std::string bad_bounds = s;  // slice 0 lb := +1e308 > ub
  const double big = 1e308;
  std::memcpy(&bad_bounds[8 + 4 + 4 + 8 + 4 * 8 + 8], &big, 8);
  std::istringstream b(bad_bounds);
  EXPECT_THROW(load_tube(b), Error);
  std::string bad_times = s;  // t_1 := t_0
  std::memset(&bad_times[8 + 4 + 4 + 8 + 8], 0, 8);
  std::istringstream t(bad_times);
  EXPECT_THROW(load_tube(t), Error);
  std::istringstream other(s);
  EXPECT_THROW(load_tube(other, TDomain::create(0.0, 2.0, 0.5)), DimensionError);
}

namespace {

std::string load_error(const std::string& path) {
  return test::error_of([&] { load_tube(path); });
}

using test::temp_file;

}  // namespace

TEST(TubeIo, RejectsTrailingBytesAndDirectories) {
  const std::string s = bytes_of(sample_tube());
  const Tube x = sample_tube();
  EXPECT_EQ(load_tube(temp_file("sillage_exact.tube", s), x.tdomain()), x);
  const std::string trailing = temp_file("sillage_trailing.tube", s + "xyz");
  EXPECT_EQ(load_error(trailing),
            "load tube: '" + trailing + "' has trailing bytes after the Tube, from byte " + std::to_string(s.size()));
  EXPECT_EQ(load_error("/tmp"), "load tube: '/tmp' is a directory, not a tube file");
}

// A gate disjoint from its slice is a value (a tube that holds no trajectory,
// which a network reports as no solution): it loads as it was saved.
TEST(TubeIo, AGateOffItsSliceLoadsAsSaved) {
  Tube x = sample_tube();
  x.set_gate(1, Interval(5));  // slice 0 = [0, 1]
  const std::string file = temp_file("sillage_disjoint.tube", bytes_of(x));
  EXPECT_EQ(load_tube(file, x.tdomain()), x);
  EXPECT_EQ(load_tube(file).gate(1), Interval(5));
}

// A file that is not a tube file (a problem file given to `sillage show`) is named in the message.
TEST(TubeIo, ErrorsOfAFileNameIt) {
  const std::string toml = temp_file("sillage_robot.toml", "[time]\ndomain = [0, 1]\n");
  EXPECT_EQ(load_error(toml), "load tube: '" + toml + "': not a sillage tube file (bad magic number at byte 0)");
  const std::string s = bytes_of(sample_tube());
  const std::string cut = temp_file("sillage_cut.tube", s.substr(0, 20));
  EXPECT_EQ(load_error(cut), "load tube: '" + cut + "': file truncated at byte 20 while reading the number of time points");
  std::istringstream is("not a tube");  // a stream has no name
  try {
    load_tube(is);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "load tube: not a sillage tube file (bad magic number at byte 0)");
  }
}
