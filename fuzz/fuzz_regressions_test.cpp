// Every input that once crashed a reader (fuzz/regressions/TARGET/, committed with the fix)
// is replayed through the same target as the fuzzers (fuzz/fuzz_inputs.h): each must end
// normally or with the reader's own error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz_inputs.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryCommittedCrashInputEndsCleanly) {
  int replayed = 0;
  for (const auto& [name, target] : fuzz::targets()) {
    const fs::path folder = fs::path(OFLAB_FUZZ_REGRESSIONS_DIR) / name;
    ASSERT_TRUE(fs::is_directory(folder)) << folder;
    for (const auto& entry : fs::directory_iterator(folder)) {
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      EXPECT_NO_THROW(target(bytes.str())) << entry.path();
      ++replayed;
    }
  }
  EXPECT_GE(replayed, 15) << "the findings of manual/robustness.md each have an input";
}

}  // namespace
}  // namespace oflab
