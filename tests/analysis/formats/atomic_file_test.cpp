// Outputs written whole (formats/atomic_file.h) and inputs read safely (formats/input_file.h).
#include "formats/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "formats/input_file.h"
#include "formats/json_fields.h"
#include "formats/scene_file.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

using testing::file_contents;

// The names in `dir`, temporaries included.
int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesWholeWithTheUmasksMode) {
  const fs::path dir = testing::fresh_test_dir("oflab-atomic");
  const mode_t old = ::umask(022);
  write_file_atomically((dir / "a.txt").string(), "hello", Overwrite::kRefuse);
  ::umask(old);
  EXPECT_EQ(file_contents(dir / "a.txt"), "hello");
  struct stat st;
  ASSERT_EQ(::stat((dir / "a.txt").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
  EXPECT_EQ(entries(dir), 1);  // no temporary left
  fs::remove_all(dir);
}

TEST(AtomicFile, AnUncommittedFileLeavesTheOldOneAndNoTemporary) {
  const fs::path dir = testing::fresh_test_dir("oflab-atomic");
  std::ofstream(dir / "keep.txt") << "old";
  {
    AtomicFile file((dir / "keep.txt").string(), Overwrite::kReplace);
    file.write("new, but the run fails");
    EXPECT_EQ(entries(dir), 2);  // the temporary, beside the target
  }
  EXPECT_EQ(file_contents(dir / "keep.txt"), "old");
  EXPECT_EQ(entries(dir), 1);
  fs::remove_all(dir);
}

TEST(AtomicFile, RefusesToOverwriteWithoutReplaceAndNonRegularTargets) {
  const fs::path dir = testing::fresh_test_dir("oflab-atomic");
  std::ofstream(dir / "keep.txt") << "old";
  EXPECT_THROW(write_file_atomically((dir / "keep.txt").string(), "x", Overwrite::kRefuse),
               FileWriteError);
  EXPECT_THROW(check_output_file(dir.string(), Overwrite::kReplace), FileWriteError);
  EXPECT_THROW(check_output_file("/dev/full", Overwrite::kReplace), FileWriteError);
  // A file that appears between the check and the commit is not overwritten either.
  AtomicFile late((dir / "late.txt").string(), Overwrite::kRefuse);
  late.write("mine");
  std::ofstream(dir / "late.txt") << "theirs";
  EXPECT_THROW(late.commit(), FileWriteError);
  EXPECT_EQ(file_contents(dir / "late.txt"), "theirs");
  EXPECT_EQ(entries(dir), 2);
  fs::remove_all(dir);
}

TEST(AtomicFile, FollowsALinkAndKeepsIt) {
  const fs::path dir = testing::fresh_test_dir("oflab-atomic");
  std::ofstream(dir / "real.txt") << "old";
  fs::create_symlink("real.txt", dir / "link.txt");
  write_file_atomically((dir / "link.txt").string(), "new", Overwrite::kReplace);
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(file_contents(dir / "real.txt"), "new");
  fs::remove_all(dir);
}

TEST(AtomicDir, AppearsWholeOnCommitAndReplaceLeavesNoStaleFile) {
  const fs::path dir = testing::fresh_test_dir("oflab-atomic");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  std::ofstream(out / "stale.csv") << "an earlier run";
  EXPECT_THROW(AtomicDir(out.string(), Overwrite::kRefuse), FileWriteError);
  {
    AtomicDir fresh(out.string(), Overwrite::kReplace);
    write_file_inside(fresh.path() + "/summary.json", "{}", "out/summary.json");
    EXPECT_FALSE(fs::exists(out / "summary.json"));  // nothing shows before the commit
    fresh.commit();
  }
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "stale.csv"));
  EXPECT_EQ(entries(dir), 1);  // neither the temporary nor the old directory is left
  {
    AtomicDir failed(out.string(), Overwrite::kReplace);
    write_file_inside(failed.path() + "/half.csv", "1,2", "out/half.csv");
  }  // not committed: a failed run
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "half.csv"));
  EXPECT_EQ(entries(dir), 1);
  fs::remove_all(dir);
}

TEST(AtomicDir, NeverReplacesTheCurrentFolderOrTheRoot) {
  EXPECT_THROW(check_output_dir(".", Overwrite::kReplace), FileWriteError);
  EXPECT_THROW(check_output_dir("/", Overwrite::kReplace), FileWriteError);
  EXPECT_THROW(check_output_dir(fs::current_path().parent_path().string(), Overwrite::kReplace),
               FileWriteError);
}

TEST(InputFile, RefusesFifosDevicesAndDirectoriesAtOnce) {
  const fs::path dir = testing::fresh_test_dir("oflab-input");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero-link");
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(read_input_file((dir / "fifo").string(), 1000).problem, InputProblem::kNotRegular);
  EXPECT_EQ(read_input_file((dir / "zero-link").string(), 1000).problem, InputProblem::kNotRegular);
  EXPECT_EQ(read_input_file("/dev/zero", 1000).problem, InputProblem::kNotRegular);
  EXPECT_EQ(read_input_file(dir.string(), 1000).problem, InputProblem::kDirectory);
  EXPECT_EQ(read_input_file((dir / "missing").string(), 1000).problem, InputProblem::kCannotOpen);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  // The readers' one-line messages.
  try {
    read_scene_file((dir / "fifo").string());
    ADD_FAILURE() << "a FIFO was read";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "fifo").string() + ": is not a regular file (a FIFO, device or socket)");
  }
  fs::remove_all(dir);
}

TEST(InputFile, ChecksTheSizeReadNotTheSizeClaimed) {
  // /proc files claim a size of 0 and hold more.
  EXPECT_EQ(read_input_file("/proc/self/maps", 16).problem, InputProblem::kTooLarge);
  const InputFile whole = read_input_file("/proc/self/maps", 1 << 24);
  EXPECT_EQ(whole.problem, InputProblem::kNone);
  EXPECT_GT(whole.bytes.size(), 16u);
  const fs::path dir = testing::fresh_test_dir("oflab-input");
  std::ofstream(dir / "ten.txt") << "0123456789";
  EXPECT_EQ(read_input_file((dir / "ten.txt").string(), 10).bytes, "0123456789");
  EXPECT_EQ(read_input_file((dir / "ten.txt").string(), 9).problem, InputProblem::kTooLarge);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
