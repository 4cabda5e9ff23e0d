// Scratch directories for tests that write files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace oflab::testing {

// The running test's directory, <system temp>/<prefix>-<process id>-<test name>, created
// when missing but not emptied: for helpers that put several files into it during one
// test. The process id keeps the suites of several trees on one machine apart.
inline std::filesystem::path test_dir(const std::string& prefix) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / (prefix + "-" + std::to_string(::getpid()) + "-" +
                                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::create_directories(dir);
  return dir;
}

// The same directory, fresh and empty (emptied first if it exists). The caller removes it
// when done.
inline std::filesystem::path fresh_test_dir(const std::string& prefix) {
  const std::filesystem::path dir = test_dir(prefix);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The bytes of `file` ("" when it cannot be read).
inline std::string file_contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace oflab::testing
