// Scratch directories for tests that write files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace oflab::testing {

// A fresh, empty directory for the running test: <system temp>/<prefix>-<process id>-<test
// name>, emptied first if it exists. The process id keeps the suites of several trees on
// one machine apart. The caller removes it when done.
inline std::filesystem::path fresh_test_dir(const std::string& prefix) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() /
                       (prefix + "-" + std::to_string(::getpid()) + "-" +
                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace oflab::testing
