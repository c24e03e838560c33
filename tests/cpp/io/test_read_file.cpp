// The size limit of the files the library reads (read_file.h): a file past
// it, a pipe that goes on, a device, are refused with the file named, and
// quickly (nothing past the limit is read).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>

#include "kit/files.h"
#include "sillage/error.h"
#include "sillage/io/csv.h"
#include "sillage/read_file.h"
#include "sillage/tube/tube_io.h"

using namespace sillage;

namespace {

// The limit set while it lives, the default after.
struct Limit {
  explicit Limit(std::uint64_t n) { set_max_file_bytes(n); }
  ~Limit() { set_max_file_bytes(kDefaultMaxFileBytes); }
};

using test::error_of;
const std::string kHint = "; raise it with SILLAGE_MAX_FILE_BYTES=<bytes> or set_max_file_bytes(bytes) (0: no limit)";

}  // namespace

TEST(ReadFile, DefaultLimitIsTwoGiB) {
  EXPECT_EQ(kDefaultMaxFileBytes, 2147483648u);
  EXPECT_EQ(max_file_bytes(), kDefaultMaxFileBytes);
}

TEST(ReadFile, AFileLargerThanTheLimitIsRefusedUnread) {
  // 3 GiB with no data written (a sparse file): refused from its size alone.
  const std::string path = testing::TempDir() + "sillage_huge.csv";
  std::ofstream(path, std::ios::binary) << "t,x\n";
  ASSERT_EQ(truncate(path.c_str(), 3ll << 30), 0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(error_of([&] { CsvTable::read(path); }),
            "CsvTable::read: '" + path +
                "' is 3221225472 bytes (3.0 GiB), more than the limit of 2147483648 bytes (2.0 GiB)" + kHint);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  std::remove(path.c_str());
}

TEST(ReadFile, TheLimitCanBeChanged) {
  const std::string csv = test::temp_file("sillage_limit.csv", "t,x\n0,1\n1,2\n");  // 12 bytes
  const std::string tube = testing::TempDir() + "sillage_limit.tube";
  save(Tube(TDomain::create(0.0, 1.0, 0.5), Interval(0, 1)), tube);  // 136 bytes
  {
    const Limit limit(11);
    EXPECT_EQ(error_of([&] { CsvTable::read(csv); }),
              "CsvTable::read: '" + csv + "' is 12 bytes, more than the limit of 11 bytes" + kHint);
    EXPECT_EQ(error_of([&] { load_tube(tube); }),
              "load tube: '" + tube + "' is 136 bytes, more than the limit of 11 bytes" + kHint);
  }
  {
    const Limit none(0);
    EXPECT_EQ(CsvTable::read(csv).nb_rows(), 2u);
  }
  const Limit exact(136);
  EXPECT_EQ(load_tube(tube).nb_slices(), 2u);
}

TEST(ReadFile, APipeIsReadUpToTheLimitOnly) {
  const std::string path = testing::TempDir() + "sillage_pipe.csv";
  std::remove(path.c_str());
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  const auto old = std::signal(SIGPIPE, SIG_IGN);  // the writer sees an error, not a signal, when the reader stops
  // A writer that would go on for 64 MiB; the reader stops past 1000 bytes.
  std::thread writer([&] {
    std::ofstream out(path, std::ios::binary);
    const std::string line = "0,1\n";
    for (int i = 0; i < (16 << 20) && out; ++i) out << line;
  });
  {
    const Limit limit(1000);
    EXPECT_EQ(error_of([&] { CsvTable::read(path); }),
              "CsvTable::read: '" + path + "' holds more than 1000 bytes, the limit" + kHint);
  }
  writer.join();  // its stream fails once the reader closed the pipe
  std::signal(SIGPIPE, old);
  std::remove(path.c_str());
}

TEST(ReadFile, DevicesAndFoldersAreRefused) {
  EXPECT_EQ(error_of([] { CsvTable::read("/dev/zero"); }),
            "CsvTable::read: '/dev/zero' is a device, not a CSV file (a device may never end)");
  EXPECT_EQ(error_of([] { load_tube("/dev/urandom"); }),
            "load tube: '/dev/urandom' is a device, not a tube file (a device may never end)");
  EXPECT_EQ(error_of([] { CsvTable::read("/tmp"); }), "CsvTable::read: '/tmp' is a directory, not a CSV file");
  EXPECT_EQ(error_of([] { CsvTable::read("/no/such.csv"); }), "CsvTable::read: '/no/such.csv': no such file");
}
