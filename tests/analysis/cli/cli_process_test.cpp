// The real oflab-cli binary in a child process, where a test can see what a user sees: its
// exit status (a signal, an abort), its wall time and its peak memory.
//
// - Long runs (ctest label `soak`): 100 000 frames of the loop script keep the peak
//   resident memory within 10 % of a 1000-frame run (manual/robustness.md, "Long runs").
// - Hostile inputs: every committed fuzz regression input and the hand-made files
//   end, under a 2 GB address-space limit, within 60 s with exit status 0 or 2 and at most a
//   one-line message (manual/robustness.md, "Limits").
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli/commands.h"
#include "formats/datasets.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

constexpr long kAddressSpaceLimit = 2L << 30;  // bytes: the 2 GB
constexpr double kTimeLimitSeconds = 60.0;

struct ChildResult {
  bool exited = false;  // false: killed by a signal (or by the time limit)
  int code = -1;        // exit status when exited
  int signal = 0;
  bool timed_out = false;
  double seconds = 0.0;   // wall time
  long peak_rss_kb = 0;   // getrusage ru_maxrss of the child
  std::string out, err;   // what it wrote
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs oflab-cli with `args` in a child (stdout and stderr into files of `dir`), its
// address space limited to `address_space` bytes (0: no limit), killed after `limit_s`
// seconds of wall time.
ChildResult run_cli_child(const std::vector<std::string>& args, const fs::path& dir,
                          long address_space, double limit_s) {
  const fs::path out = dir / "child.out", err = dir / "child.err";
  std::vector<char*> argv{const_cast<char*>(OFLAB_CLI_BINARY)};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (address_space > 0) {
      const rlimit limit{static_cast<rlim_t>(address_space), static_cast<rlim_t>(address_space)};
      ::setrlimit(RLIMIT_AS, &limit);
    }
    ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
    ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    ::execv(OFLAB_CLI_BINARY, argv.data());
    ::_exit(127);
  }
  ChildResult r;
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
    const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
    if (t.count() > limit_s && !r.timed_out) {
      r.timed_out = true;
      ::kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.exited = WIFEXITED(status);
  r.code = r.exited ? WEXITSTATUS(status) : -1;
  r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  r.peak_rss_kb = usage.ru_maxrss;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

// ---- Long runs ----

// The loop script (datasets/scripts/loop.json) at a quarter of its image size and focal
// length, the same motion seen smaller, so 100 000 frames with the re-render baseline and
// PSNR take seconds.
fs::path small_loop(const fs::path& dir) {
  nlohmann::json script = nlohmann::json::parse(std::ifstream(resolve_script_path("loop")));
  script["camera"] = {{"focal_px", 64}, {"image", {160, 120}}};
  const fs::path file = dir / "loop-160x120.json";
  std::ofstream(file) << script.dump();
  return file;
}

// `animate` of `frames` frames of the small loop, streamed: one timed pass, no warm-up,
// the CSV written into dir/NAME as it goes.
ChildResult play_loop(const fs::path& dir, int frames, const std::string& name) {
  const int repeat = frames / 629 + 1;  // loop.json has 629 frames
  return run_cli_child({"animate", "--script", small_loop(dir).string(), "--repeat",
                        std::to_string(repeat), "--frames", std::to_string(frames),
                        "--repeat-timing", "1", "--no-warm-up", "--quiet", "--json", "--out",
                        (dir / name).string()},
                       dir, 0, 600.0);
}

long csv_rows(const fs::path& file) {
  std::ifstream in(file);
  long lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines - 1;  // the header
}

TEST(LongRun, HundredThousandFramesPeakWithinTenPercentOfAThousand) {
  const fs::path dir = testing::fresh_test_dir("oflab-long-run");
  const ChildResult short_run = play_loop(dir, 1000, "short");
  ASSERT_EQ(short_run.code, 0) << short_run.err;
  const ChildResult long_run = play_loop(dir, 100000, "long");
  ASSERT_EQ(long_run.code, 0) << long_run.err;
  EXPECT_EQ(nlohmann::json::parse(long_run.out).at("frames"), 100000);
  EXPECT_EQ(csv_rows(dir / "long" / "frames.csv"), 100000);
  EXPECT_EQ(csv_rows(dir / "short" / "frames.csv"), 1000);
  std::cout << "peak resident memory: 1000 frames " << short_run.peak_rss_kb
            << " KB, 100000 frames " << long_run.peak_rss_kb << " KB ("
            << long_run.seconds << " s)\n";
  EXPECT_LE(long_run.peak_rss_kb, short_run.peak_rss_kb * 1.10);
  fs::remove_all(dir);
}

// ---- Hostile inputs ----

// The command line that feeds a regression input of fuzz target `target` (the folder
// under fuzz/regressions/) to oflab-cli; empty for a target the CLI does not read.
std::vector<std::string> command_for(const std::string& target, const fs::path& input,
                                     const fs::path& dir) {
  const std::string file = input.string();
  if (target == "motion-script") return {"animate", "--script", file, "--frames", "20"};
  if (target == "viewer-script")
    return {"animate", "--scene", "four-cubes", "--script", file, "--frames", "5"};
  if (target == "scene") return {"animate", "--scene", file, "--script", "circle", "--frames", "5"};
  if (target == "image") return {"animate", "--script", "zoom", "--texture", file, "--frames", "5"};
  if (target == "obj") return {"make-scene", "--from-obj", file, "--out", (dir / "o.json").string(),
                               "--force"};
  if (target == "command-line") {
    std::vector<std::string> args;
    std::ifstream in(input);
    for (std::string a; std::getline(in, a, '\n');) args.push_back(a);
    return args;
  }
  return {};  // session: the GUI's files
}

void expect_ends_cleanly(const std::vector<std::string>& args, const fs::path& dir,
                         const std::string& what) {
  const ChildResult r = run_cli_child(args, dir, kAddressSpaceLimit, kTimeLimitSeconds);
  EXPECT_FALSE(r.timed_out) << what;
  EXPECT_LT(r.seconds, kTimeLimitSeconds) << what;
  ASSERT_TRUE(r.exited) << what << ": signal " << r.signal << "\n" << r.err;
  EXPECT_TRUE(r.code == 0 || r.code == 2) << what << ": exit " << r.code << "\n" << r.err;
  if (r.code == 2) {
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << what << ": " << r.err;
  }
}

TEST(HostileInputs, EveryRegressionInputEndsWithin60sAnd2GBWithACleanStatus) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-process");
  int run = 0;
  for (const auto& target : fs::directory_iterator(OFLAB_FUZZ_REGRESSIONS_DIR)) {
    for (const auto& input : fs::directory_iterator(target.path())) {
      fs::path file = input.path();
      if (target.path().filename() == "obj") {  // animate --scene knows OBJ by its extension
        expect_ends_cleanly({"animate", "--scene", file.string(), "--script", "circle",
                             "--frames", "5"},
                            dir, file.string() + " as --scene");
      }
      const auto args = command_for(target.path().filename().string(), file, dir);
      if (args.empty()) continue;
      expect_ends_cleanly(args, dir, file.string());
      ++run;
    }
  }
  EXPECT_GE(run, 15);
  fs::remove_all(dir);
}

// The hand-made files that are not fuzz inputs: a plane closer to the eye than the
// warp can take, a plane of size 1e-300, focal lengths of 1e6 and 1e-300.
TEST(HostileInputs, DegeneratePlanesAndCamerasEndWithin60sAnd2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-planes");
  const nlohmann::json base = nlohmann::json::parse(std::ifstream(resolve_script_path("zoom")));
  std::vector<nlohmann::json> scripts(4, base);
  scripts[0]["plane"]["point"] = {0, 0, 1e-6};
  scripts[1]["plane"]["size"] = {1e-300, 1e-300};
  scripts[2]["camera"]["focal_px"] = 1e6;
  scripts[3]["camera"]["focal_px"] = 1e-300;
  for (std::size_t i = 0; i < scripts.size(); ++i) {
    const fs::path file = dir / ("degenerate-" + std::to_string(i) + ".json");
    std::ofstream(file) << scripts[i].dump();
    expect_ends_cleanly({"animate", "--script", file.string(), "--frames", "20"}, dir,
                        scripts[i].dump());
  }
  fs::remove_all(dir);
}

// ---- The last resort of main (oflab-cli's and oflab's) ----

TEST(LastResort, AnEscapedExceptionIsOneLineAndTheInternalErrorCode) {
  std::ostringstream err;
  EXPECT_EQ(run_guarded("oflab-cli", [] { return 0; }, err), 0);
  EXPECT_EQ(run_guarded("oflab-cli", [] { return 2; }, err), 2);
  EXPECT_EQ(err.str(), "");
  EXPECT_EQ(run_guarded("oflab-cli", []() -> int { throw std::runtime_error("two\nlines"); }, err),
            kInternalErrorExitCode);
  EXPECT_EQ(err.str(), "oflab-cli: internal error: two lines\n");
  err.str("");
  EXPECT_EQ(run_guarded("oflab", []() -> int { throw std::bad_alloc(); }, err),
            kInternalErrorExitCode);
  EXPECT_EQ(err.str(), "oflab: internal error: std::bad_alloc\n");
  err.str("");
  EXPECT_EQ(run_guarded("oflab", []() -> int { throw 42; }, err), kInternalErrorExitCode);
  EXPECT_EQ(err.str(), "oflab: internal error: an unknown exception\n");
  EXPECT_NE(kInternalErrorExitCode, 2);  // not the bad-input code
}

}  // namespace
}  // namespace oflab
