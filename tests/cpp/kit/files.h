#pragma once
// Files written for a test, and the message of what a call throws: for the
// tests of what a bad file says.
#include <gtest/gtest.h>

#include <exception>
#include <fstream>
#include <string>

namespace sillage::test {

// Writes `bytes` to the test's temporary folder under `name`; returns the path.
inline std::string temp_file(const std::string& name, const std::string& bytes) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The message of the exception `call` throws, "no error" if it returns.
template <class Call>
std::string error_of(Call call) {
  try {
    call();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace sillage::test
