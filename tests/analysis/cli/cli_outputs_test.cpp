// What the real oflab-cli leaves on disk when writing fails or two runs write the same output
// (formats/atomic_file.h, manual/robustness.md "How outputs are written"), and what it does
// with inputs that are not regular files. A full disk is a child whose file size limit
// (RLIMIT_FSIZE, with SIGXFSZ ignored) stops its writes with EFBIG part way.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scratch_dir.h"
#include "video_decode.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

using testing::file_contents;

struct Child {
  pid_t pid = -1;
  fs::path err;
};

// Starts oflab-cli with `args`, stdout and stderr into DIR/TAG.out and .err; a `max_file`
// above 0 limits the size of every file it writes (bytes).
Child start(const std::vector<std::string>& args, const fs::path& dir, const std::string& tag,
            long max_file = 0) {
  Child c;
  c.err = dir / (tag + ".err");
  const fs::path out = dir / (tag + ".out");
  std::vector<char*> argv{const_cast<char*>(OFLAB_CLI_BINARY)};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  c.pid = ::fork();
  if (c.pid == 0) {
    ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
    ::dup2(::open(c.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    if (max_file > 0) {
      ::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead
      const rlimit limit{static_cast<rlim_t>(max_file), static_cast<rlim_t>(max_file)};
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ::alarm(120);  // a hung child ends
    ::execv(OFLAB_CLI_BINARY, argv.data());
    ::_exit(127);
  }
  return c;
}

// The child's exit code (-1 for a signal) and its stderr.
std::pair<int, std::string> finish(const Child& c) {
  int status = 0;
  ::waitpid(c.pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, file_contents(c.err)};
}

std::pair<int, std::string> run(const std::vector<std::string>& args, const fs::path& dir,
                                long max_file = 0) {
  return finish(start(args, dir, "run", max_file));
}

// The names in `dir` other than the children's stdout and stderr files.
std::vector<std::string> names(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".out" && ext != ".err") found.push_back(e.path().filename().string());
  }
  std::sort(found.begin(), found.end());
  return found;
}

bool one_line(const std::string& err) { return !err.empty() && err.find('\n') == err.size() - 1; }

TEST(FailedWrites, DevFullIsRefusedWithANonZeroExit) {
  const fs::path dir = testing::fresh_test_dir("oflab-outputs");
  const auto [code, err] = run({"make-butterfly", "--out", "/dev/full", "--force"}, dir);
  EXPECT_NE(code, 0);
  EXPECT_TRUE(one_line(err)) << err;
  EXPECT_NE(err.find("/dev/full"), std::string::npos) << err;
  for (const auto& e : fs::directory_iterator("/dev")) {
    EXPECT_EQ(e.path().filename().string().rfind(".full.tmp-", 0), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(FailedWrites, AFullDiskLeavesTheOldFileAndNoPartialOne) {
  const fs::path dir = testing::fresh_test_dir("oflab-outputs");
  std::ofstream(dir / "b.png") << "the user's file";
  const auto [code, err] =
      run({"make-butterfly", "--out", (dir / "b.png").string(), "--force"}, dir, 4096);
  EXPECT_EQ(code, 1);
  EXPECT_TRUE(one_line(err)) << err;
  EXPECT_NE(err.find("cannot write"), std::string::npos) << err;
  EXPECT_EQ(file_contents(dir / "b.png"), "the user's file");
  EXPECT_EQ(names(dir), std::vector<std::string>{"b.png"});
  // The same for a scene file and a new file: nothing is left.
  const auto [code2, err2] =
      run({"make-scene", "--cubes", "200", "--out", (dir / "s.json").string()}, dir, 4096);
  EXPECT_EQ(code2, 1);
  EXPECT_TRUE(one_line(err2)) << err2;
  EXPECT_EQ(names(dir), std::vector<std::string>{"b.png"});
  fs::remove_all(dir);
}

TEST(FailedWrites, AFailedVideoRunKeepsTheOldVideoAndAFailedOutDirTheOldDir) {
  const fs::path dir = testing::fresh_test_dir("oflab-outputs");
  std::ofstream(dir / "keep.gif") << "the user's GIF";
  const auto [code, err] = run({"animate", "--script", "zoom", "--frames", "40", "--repeat-timing",
                                "1", "--quiet", "--video", (dir / "keep.gif").string(), "--force"},
                               dir, 30000);
  EXPECT_EQ(code, 1);
  EXPECT_TRUE(one_line(err)) << err;
  EXPECT_TRUE(file_contents(dir / "keep.gif") == "the user's GIF");  // (no GIF bytes printed)
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "frames.csv") << "an earlier run";
  const auto [code2, err2] =
      run({"animate", "--script", "loop", "--repeat-timing", "1", "--no-warm-up", "--quiet",
           "--out", (dir / "out").string(), "--force"},
          dir, 20000);
  EXPECT_EQ(code2, 1);
  EXPECT_TRUE(one_line(err2)) << err2;
  EXPECT_NE(err2.find("frames.csv"), std::string::npos) << err2;
  EXPECT_EQ(file_contents(dir / "out" / "frames.csv"), "an earlier run");
  EXPECT_EQ(names(dir), (std::vector<std::string>{"keep.gif", "out"}));
  fs::remove_all(dir);
}

TEST(ConcurrentRuns, TwoRunsWritingTheSameOutputsLeaveOneWholeOutput) {
  const fs::path dir = testing::fresh_test_dir("oflab-outputs");
  const mode_t old = ::umask(022);
  const std::vector<std::string> video = {"animate", "--script",        "zoom", "--frames",
                                          "25",      "--repeat-timing", "1",    "--quiet"};
  std::vector<std::string> a = video, b = video;
  for (auto* args : {&a, &b}) {
    args->insert(args->end(), {"--video", (dir / "same.gif").string(), "--force"});
  }
  const std::vector<std::string> compare = {"compare",
                                            "--script",
                                            "zoom",
                                            "--policies",
                                            "perspective,rerender",
                                            "--frames",
                                            "25",
                                            "--repeat-timing",
                                            "1",
                                            "--quiet",
                                            "--force",
                                            "--out",
                                            (dir / "cmp").string()};
  const Child c1 = start(a, dir, "a"), c2 = start(b, dir, "b");
  const Child c3 = start(compare, dir, "c"), c4 = start(compare, dir, "d");
  ::umask(old);
  for (const Child& c : {c1, c2, c3, c4}) {
    const auto [code, err] = finish(c);
    EXPECT_EQ(code, 0) << err;
  }
  const testing::SlurpedGif gif = testing::read_gif((dir / "same.gif").string());
  ASSERT_TRUE(gif);
  EXPECT_EQ(gif->ImageCount, 25);
  struct stat st;
  ASSERT_EQ(::stat((dir / "same.gif").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);  // the umask's mode, as for MP4 and OGV
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir / "cmp")) {
    files.push_back(e.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"perspective.csv", "rerender.csv", "summary.csv"}));
  std::ifstream summary(dir / "cmp" / "summary.csv");
  int rows = 0;
  for (std::string line; std::getline(summary, line);) ++rows;
  EXPECT_EQ(rows, 3);
  EXPECT_EQ(names(dir), (std::vector<std::string>{"cmp", "same.gif"}));  // no temporaries
  fs::remove_all(dir);
}

TEST(NonRegularInputs, AreRefusedAtOnceWithOneLine) {
  const fs::path dir = testing::fresh_test_dir("oflab-outputs");
  ASSERT_EQ(::mkfifo((dir / "fifo.obj").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.obj");
  fs::create_directories(dir / "folder.obj");
  for (const std::string input : {"/dev/zero", "zero.obj", "fifo.obj", "folder.obj"}) {
    const std::string path = input[0] == '/' ? input : (dir / input).string();
    const auto [code, err] =
        run({"make-scene", "--from-obj", path, "--out", (dir / "s.json").string()}, dir);
    EXPECT_EQ(code, 2) << input;
    EXPECT_TRUE(one_line(err)) << err;
    EXPECT_NE(err.find(path), std::string::npos) << err;
  }
  const auto [code, err] = run({"animate", "--script", (dir / "fifo.obj").string()}, dir);
  EXPECT_EQ(code, 2);
  EXPECT_TRUE(one_line(err)) << err;
  const auto [code2, err2] =
      run({"animate", "--script", "zoom", "--texture", (dir / "fifo.obj").string()}, dir);
  EXPECT_EQ(code2, 2);
  EXPECT_TRUE(one_line(err2)) << err2;
  EXPECT_FALSE(fs::exists(dir / "s.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
